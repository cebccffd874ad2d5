// Runner side of glsl/passes/cascade_blend.comp: the visibilities a technique
// produced on each cascade, blended into one by view depth.
#pragma once

#include <memory>
#include <vector>

#include "device/query_device.h"
#include "gl/texture.h"
#include "shader/source_tree.h"

namespace pn {

// What blends the cascades' visibilities (cascades.glsl): the camera's view depth, the splits
// and the transition band.
struct CascadeBlend {
  const DeviceTexture* view_depth = nullptr;  // screen² RGBA32F: z the camera's view depth, w = 1 where a surface is seen
  float split_far[4] = {0, 0, 0, 0};     // C_1 ... C_m
  float near = 0;                        // C_0
  float band = 0;
  bool fade_last = true;
};

class CascadeBlendPass {
 public:
  CascadeBlendPass(const QueryDevice& device, const SourceTree& tree);

  // One screen² R32F visibility from `visibilities` (one a cascade, nearest first, screen² R32F),
  // by `view_depth` (cascades.view_depth's texture; any executor).
  std::unique_ptr<DeviceTexture> blend(const DeviceTexture& view_depth, const CascadeBlend& cascades,
                                       const std::vector<const DeviceTexture*>& visibilities, int screen_size) const;
  // The same by cascades.view_depth. Throws Error without one.
  std::unique_ptr<DeviceTexture> blend(const CascadeBlend& cascades,
                                       const std::vector<const DeviceTexture*>& visibilities, int screen_size) const;

 private:
  const QueryDevice* device_;
  std::unique_ptr<QueryProgram> program_;
  std::unique_ptr<DeviceTexture> unused_;  // bound where a cascade is missing (1×1, never read)
};

}  // namespace pn
