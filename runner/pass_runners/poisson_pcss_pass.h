// Runner side of glsl/passes/poisson_pcss_query.comp: poisson_pcss.glsl over a
// batch of disks, the disk read in place from the pass's uniform block, or from the
// pass's constant (`penumbra poisson --count 16 --seed 1`, pasted into the pass).
#pragma once

#include <vector>

#include "pass_runners/query_pass.h"
#include "sampling/sample_table_generator.h"
#include "shader/source_tree.h"

namespace pn {

// Where the pass takes its disk from.
enum class PoissonDiskSource {
  block,      // the block's points in place (PN_POISSON_DISK_ARRAY, pnPoissonOcclusionDisk), as the pipeline
  constant,   // the pasted constant in place (PN_POISSON_DISK_ARRAY, pnPoissonOcclusionDisk)
};

// The constant disk pasted into poisson_pcss_query.comp.
inline constexpr int kPoissonQueryConstCount = 16;
inline constexpr unsigned kPoissonQueryConstSeed = 1;

struct PoissonPcssGpuQuery {
  float centre_x = 0.0f, centre_y = 0.0f, diameter = 0.0f;  // texels
  float receiver_depth = 0.0f, bias = 0.0f;
  int count = 0;
  float rotation_x = 1.0f, rotation_y = 0.0f;
};

struct PoissonPcssGpuResult {
  float occluders = 0.0f, depth_sum = 0.0f, samples = 0.0f;
  float ratio = 0.0f;  // pnPoissonBlockerMean of the sums at odd query indices, pnPoissonOccludedFraction at even
};

class PoissonPcssQueryPass {
 public:
  PoissonPcssQueryPass(const QueryDevice& device, const SourceTree& tree);

  // `points` (at most PN_POISSON_MAX_SAMPLES; the rest of the block's array is zero) go into the
  // uniform block; `source` says which disk the module reads (constant: the pasted one, points unused).
  std::vector<PoissonPcssGpuResult> run(const DeviceTexture& depth_map, const std::vector<Sample>& points,
                                        PoissonDiskSource source, const std::vector<PoissonPcssGpuQuery>& queries) const;

 private:
  QueryPass query_;        // PN_POISSON_DISK_ARRAY = the pasted constant
  QueryPass block_query_;  // PN_POISSON_DISK_ARRAY = the block's array (PN_QUERY_DISK_IN_BLOCK)
};

}  // namespace pn
