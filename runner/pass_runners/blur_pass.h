// Runner side of glsl/passes/blur.comp: the two 1-D dispatches (x, then y)
// that blur an R32F, RG32F or RGBA32F texture with glsl/blur.glsl.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "device/program_variants.h"
#include "device/query_device.h"
#include "modules/blur_face.h"
#include "shader/source_tree.h"

namespace pn {

class BlurPass {
 public:
  // Flattens and compiles passes/blur.comp from `tree` (a user's copy under
  // --glsl-root too), once per variant: plain or depth-aware, fixed or adaptive
  // radius, 1, 2 or 4 channels (the single-channel variants now, the others on first use).
  // Runs on any executor (device/query_device.h).
  BlurPass(const QueryDevice& device, const SourceTree& tree);

  // Returns a new width × height texture of `channels` floats (1, 2 or 4; the
  // source's format, R32F, RG32F or RGBA32F), every channel blurred alike
  // (stored as device.storage_channels(channels): RGBA32F for 2 on ES).
  // `depth` (same size, R32F) is read only when params.depth_aware, `filter_map`
  // (same size, RGBA32F, the filter-region map: .w = side in texels) only when
  // params.adaptive. Throws Error for invalid params or channel counts, and
  // when adaptive without a filter map.
  std::unique_ptr<DeviceTexture> run(const DeviceTexture& source, const DeviceTexture* depth, int width, int height,
                                     const BlurParams& params, const DeviceTexture* filter_map = nullptr,
                                     int channels = 1) const;

 private:
  const QueryProgram& program(const BlurParams& params, int channels) const;
  const QueryDevice* device_;
  ProgramVariants variants_;  // blur.comp by its PN_BLUR_PASS_* switches
};

}  // namespace pn
