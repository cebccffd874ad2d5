// Runner side of glsl/passes/traversal_query.comp (and of window_scan.comp,
// the brute-force baseline of `penumbra bench traversal`).
#pragma once

#include <vector>

#include "pass_runners/depth_pyramid_pass.h"
#include "pass_runners/minmax_mip_pass.h"
#include "pass_runners/query_pass.h"
#include "pass_runners/summed_area_pass.h"
#include "core/texel_rect.h"
#include "modules/traversal_face.h"
#include "sampling/sample_table_generator.h"
#include "shader/source_tree.h"

namespace pn {

struct TraversalQuery {
  Rect region;
  float receiver_depth = 0.0f;
  int pixel_x = 0, pixel_y = 0;
  // The mip chain's traversal only: a receiver plane (glsl/receiver_plane.glsl) through (u, v, depth)
  // with this light depth per texel; 0: none.
  float receiver_u = 0.0f, receiver_v = 0.0f;
  float gradient_u = 0.0f, gradient_v = 0.0f;
  // With TraversalSettings::area_regions: the area-weighted square (pnRegionArea) of side
  // `area_side` centred on (area_x, area_y) instead of `region`.
  float area_x = 0.0f, area_y = 0.0f, area_side = 0.0f;
};

// The same for every query of a batch.
struct TraversalSettings {
  float bias = 0.0f;
  int leaf_side = 1;
  LeafMode leaf_mode = LeafMode::sampled;
  int node_budget = PN_TRAVERSAL_NO_BUDGET;
  DepthSums depth_sums = DepthSums::table;  // the mip chain's traversal
  int grid = 0;  // the mip chain: > 0 counts over pnGridRegionMip's grid instead of traversing
  int leaf_divisor = 0;  // > 0: leaves of at least the region's longer side / this (pnTraversalLeafSide)
  bool area_regions = false;  // the mip chain: each query's area square, pnTraverseAreaMipPlane
  bool region_leaf = false;   // the leaf side from pnTraversalRegionLeafSide (Fast PCSS's)
};

// What a traversal reads: the decreased pyramid, or the aligned mip chain
// with its summed-area table of depth (the table only for DepthSums::table).
struct TraversalStructure {
  const DepthPyramid* pyramid = nullptr;
  const MinMaxMipChain* mip = nullptr;
  const SummedAreaTable* depth_sums = nullptr;
};

std::unique_ptr<DeviceTexture> upload_sample_table(const QueryDevice& device, const SampleTable& table);

// A query's result as the GPU returns it: the counts, and the module's own blocker mean and
// occluded fraction of them (pnTraversalBlockerMean, pnTraversalOccludedFraction), so a check
// proves those calls rather than recomputing them here.
struct TraversalReadback : TraversalResult {
  double called_blocker_mean = 0.0;
  double called_occluded_fraction = 0.0;
};

// Queries on the GPU and their result images; read() returns one result per query.
class TraversalBatch {
 public:
  TraversalBatch(const QueryDevice& device, const std::vector<TraversalQuery>& queries, bool area_regions = false);
  std::vector<TraversalReadback> read() const;

 private:
  friend class TraversalPass;
  friend class WindowScanPass;
  std::size_t count_;
  std::unique_ptr<QueryBatch> batch_;  // inputs A, B, E; results C, D
};

class TraversalPass {
 public:
  TraversalPass(const QueryDevice& device, const SourceTree& tree);
  // Throws Error unless the structure holds a pyramid or a mip chain (with depth sums when wanted).
  void dispatch(const TraversalStructure& structure, const DeviceTexture& sample_table, const TraversalBatch& batch,
                const TraversalSettings& settings) const;
  void dispatch(const DepthPyramid& pyramid, const DeviceTexture& sample_table, const TraversalBatch& batch,
                const TraversalSettings& settings) const {
    dispatch(TraversalStructure{&pyramid}, sample_table, batch, settings);
  }

 private:
  QueryPass query_;
  std::unique_ptr<DeviceTexture> empty_array_, empty_2d_, empty_uint_;  // bound where the structure has none
};

// Brute force over each query's region (every texel fetched), into the same result layout.
class WindowScanPass {
 public:
  WindowScanPass(const QueryDevice& device, const SourceTree& tree);
  void dispatch(const DepthPyramid& pyramid, const TraversalBatch& batch, float bias) const;

 private:
  QueryPass query_;
};

}  // namespace pn
