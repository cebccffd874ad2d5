// Runner side of glsl/passes/vsm_moments.comp (depth map -> moments, then the
// blur pass over them), glsl/passes/vsm_query.comp (vsm.glsl's bounds for a
// batch of receivers, the check's query pass) and glsl/passes/vsm_shade.comp
// (the vsm / evsm techniques' visibility per screen pixel).
#pragma once

#include <vector>

#include "core/query_grid.h"
#include "pass_runners/blur_pass.h"
#include "pass_runners/depth_pyramid_pass.h"
#include "modules/vsm_face.h"
#include "pass_runners/query_pass.h"
#include "pass_runners/shade_pass.h"
#include "shader/source_tree.h"

namespace pn {

// A moments texture: vsm_moment_channels(kind) floats a texel, stored as the device's
// storage_channels of them (RGBA32F for two on ES).
struct VsmMoments {
  std::unique_ptr<DeviceTexture> texture;
  int size = 0;
  int channels = 2;  // logical: 2 or 4
  int stored = 2;    // the texture's channels
};

class VsmMomentsPass {
 public:
  // Compiles vsm_moments.comp once per kind (on first use) and the blur pass; on any executor.
  VsmMomentsPass(const QueryDevice& device, const SourceTree& tree);

  // The moments of every texel of an N×N R32F depth map (throws Error for a non-square map or
  // invalid params).
  VsmMoments moments(const DeviceTexture& depth_map, int width, int height, const VsmParams& params) const;
  // The moments blurred with params.blur (blur.glsl over 2 or 4 channels).
  VsmMoments blurred(const VsmMoments& moments, const VsmParams& params) const;

 private:
  const QueryDevice* device_;
  const SourceTree* tree_;
  mutable std::unique_ptr<QueryProgram> variants_[3];  // by PN_VSM_MOMENTS_KIND, each compiled on first use
  BlurPass blur_;
};

struct VsmQuery {
  int x = 0, y = 0;  // the receiver's texel
  float receiver_depth = 0.0f, bias = 0.0f;
};

// (visibility, Chebyshev bound p, reduced p, depth-range bound code) per query.
class VsmQueryPass {
 public:
  VsmQueryPass(const QueryDevice& device, const SourceTree& tree);
  std::vector<Query> run(const VsmMoments& moments, const DepthPyramid& pyramid, const std::vector<VsmQuery>& queries,
                         const VsmParams& params) const;

 private:
  QueryPass query_;
};

// Per screen pixel of a G-buffer (screen² RGBA32F: u, v in texels, light depth, valid): the
// visibility of vsm.glsl (pnVsmVisibility / pnEvsmVisibility2 / 4) with `bias`, as a new screen²
// R32F texture. Pixels that see no surface are 1.
class VsmShadePass {
 public:
  VsmShadePass(const QueryDevice& device, const SourceTree& tree);
  std::unique_ptr<DeviceTexture> run(const VsmMoments& moments, const DepthPyramid& pyramid,
                                     const DeviceTexture& gbuffer, int screen_size, const VsmParams& params,
                                     float bias, ShadeStage stage = ShadeStage::compute) const;

 private:
  ShadePass shade_;  // by PN_VSM_SHADE_KIND
};

}  // namespace pn
