// Runner side of glsl/passes/gbuffer.vert/.frag (Step 2): per screen pixel,
// (shadow-map u, v in texels, linear light depth, 1), or 0 where no surface is seen.
#pragma once

#include <cmath>
#include <memory>

#include "device/query_device.h"
#include "gl/texture.h"
#include "scene/scene.h"
#include "shader/source_tree.h"

namespace pn {

class GBufferRenderer {
 public:
  GBufferRenderer(const QueryDevice& device, const SourceTree& tree);
  // RGBA32F, rows from the bottom. normal_offset_texels > 0: the point moved
  // off its face by that many shadow-map texels first (gbuffer.frag).
  FloatTexture render(const Scene& scene, int screen_size, float normal_offset_texels = 0.0f) const {
    return render(scene, screen_size, normal_offset_texels, scene.map_light());
  }
  // For another map's light (a cascade's), keeping only the surfaces whose camera view depth
  // lies in [view_depth_lo, view_depth_hi): a pixel whose nearest surface lies outside is
  // 0, "no surface". The camera's own view and projection as `light` make channel z the view depth.
  FloatTexture render(const Scene& scene, int screen_size, float normal_offset_texels, const MapLight& light,
                      float view_depth_lo = 0.0f, float view_depth_hi = INFINITY) const;
  // The same on any executor, as a texture on the device (the forms above: a GL texture).
  std::unique_ptr<DeviceTexture> render_texture(const Scene& scene, int screen_size, float normal_offset_texels,
                                                const MapLight& light, float view_depth_lo = 0.0f,
                                                float view_depth_hi = INFINITY) const;

 private:
  const QueryDevice* device_;
  std::unique_ptr<QueryProgram> program_;
};

}  // namespace pn
