// Runner side of glsl/passes/pcf_query.comp (pcf.glsl over a batch of windows)
// and of glsl/passes/pcf_shade.comp (the pcf technique's 2×2 bilinear PCF per
// screen pixel).
#pragma once

#include <vector>

#include "core/query_grid.h"
#include "gl/compute_program.h"
#include "pass_runners/query_pass.h"
#include "pass_runners/shade_pass.h"
#include "scene/light_model.h"
#include "shader/source_tree.h"

namespace pn {

struct PcfQuery {
  int x = 0, y = 0, width = 0, height = 0;  // window origin and size, texels
  float receiver_depth = 0.0f;
  float bias = 0.0f;
  int band_rows = 0;  // 0: pnPcfWindow; b > 0: bands of b rows added up with pnPcfAddRows
};

struct PcfQueryResult {
  float occluders = 0.0f, depth_sum = 0.0f, texels = 0.0f;
  float ratio = 0.0f;  // area queries: pnPcfBlockerMean at odd query indices, pnPcfOccludedFraction at even; windows: 0
};

// pnPcfBilinearVisibility's inputs: a map position (continuous texels), a receiver depth, a bias;
// and a receiver plane's gradient (light depth per texel; 0: none, else pnPcf's plane overload).
struct PcfBilinearQuery {
  float x = 0.0f, y = 0.0f, receiver_depth = 0.0f, bias = 0.0f;
  float gradient_u = 0.0f, gradient_v = 0.0f;
};

// The area-weighted window (issue 51): pnRegionArea(centre, side, map width), its sums read by
// pnPcfAreaPlane (band_rows 0) or added up in bands of band_rows with pnPcfAddAreaRowsPlane.
struct PcfAreaQuery {
  float x = 0.0f, y = 0.0f, side = 0.0f;  // the square's centre and side, texels
  float receiver_depth = 0.0f;
  float bias = 0.0f;
  int band_rows = 0;
};

// A receiver plane for a window or area query (pnPcfWindowPlane, pnPcfAreaPlane and their bands):
// its gradient (light depth a texel) and, for a window, the receiver's (u, v) (an area query's is the
// square's centre).
struct PcfPlane {
  float gradient_u = 0.0f, gradient_v = 0.0f, centre_u = 0.0f, centre_v = 0.0f;
};

class PcfQueryPass {
 public:
  // max_side > 0 compiles the pass with that PN_PCF_MAX_SIDE; 0 keeps the module's default.
  PcfQueryPass(const QueryDevice& device, const SourceTree& tree, int max_side = 0);

  // `depth_map` is a single-channel float texture; one result per query.
  std::vector<PcfQueryResult> run(const DeviceTexture& depth_map, const std::vector<PcfQuery>& queries) const;
  // Each area query's sums: occluded area, its depth-weighted sum, the area read; and `ratio`.
  std::vector<PcfQueryResult> area(const DeviceTexture& depth_map, const std::vector<PcfAreaQuery>& queries) const;
  // The same with a receiver plane a query (planes[k]): the sums of the plane windows and squares.
  std::vector<PcfQueryResult> run(const DeviceTexture& depth_map, const std::vector<PcfQuery>& queries,
                                  const std::vector<PcfPlane>& planes) const;
  std::vector<PcfQueryResult> area(const DeviceTexture& depth_map, const std::vector<PcfAreaQuery>& queries,
                                   const std::vector<PcfPlane>& planes) const;
  // The 2×2 bilinear PCF visibility of each query.
  std::vector<float> bilinear(const DeviceTexture& depth_map, const std::vector<PcfBilinearQuery>& queries) const;

 private:
  // `c`: the plane queries' third input (empty: zeros).
  QueryResults dispatch(const DeviceTexture& depth_map, const std::vector<Query>& a, const std::vector<Query>& b,
                        std::vector<Query> c = {}) const;
  QueryPass query_;
};

// Per screen pixel of a G-buffer (screen² RGBA32F: u, v in texels, light depth, valid): the 2×2
// bilinear PCF visibility of `shadow_map` (pnPcf) with `bias`, as a new screen²
// R32F texture. The pass the pcf techniques of one context share (TechniqueResources::shared).
class PcfShadePass {
 public:
  PcfShadePass(const QueryDevice& device, const SourceTree& tree);
  // receiver_plane_tan > 0: each pixel's receiver plane from its G-buffer neighbours, slopes
  // clamped to that tangent (gbuffer_receiver_plane.glsl); 0: none.
  std::unique_ptr<DeviceTexture> run(const DeviceTexture& shadow_map, const DeviceTexture& gbuffer, int screen_size,
                                     const LightModel& light, float bias, float receiver_plane_tan,
                                     ShadeStage stage = ShadeStage::compute) const;

 private:
  ShadePass shade_;
};

}  // namespace pn
