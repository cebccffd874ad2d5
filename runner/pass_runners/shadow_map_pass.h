// Runner side of glsl/passes/shadow_depth.vert/.frag: renders a scene's
// shadow map of linear light depth (SPEC §4.7 Step 1) into an R32F texture,
// +Inf where no surface is seen (SPEC §3: no occluder).
#pragma once

#include <memory>

#include "device/query_device.h"
#include "gl/texture.h"
#include "pass_runners/scene_draw.h"
#include "scene/scene.h"
#include "shader/source_tree.h"

namespace pn {

class ShadowMapRenderer {
 public:
  ShadowMapRenderer(const QueryDevice& device, const SourceTree& tree);

  // N×N R32F texture on the device, N = light.light.map_size (the scene's light, or another view
  // and projection: a cascade's); rows from the framebuffer's bottom. Any executor.
  std::unique_ptr<DeviceTexture> render_texture(const Scene& scene, const MapLight& light) const;
  // The same as a GL texture (the device is a GL context).
  FloatTexture render(const Scene& scene) const { return render(scene, scene.map_light()); }
  FloatTexture render(const Scene& scene, const MapLight& light) const;

  // Into a kept N×N R32F target: `runs` of `geometry` (the scene's vertices) with the scene's
  // light, within `rects` (everywhere for none), over what the target holds. What the caches draw.
  void draw(const Scene& scene, const SceneGeometry& geometry, const DeviceRasterTarget& target,
            const std::vector<VertexRun>& runs, const std::vector<TexelRect>& rects = {}) const;
  // The map's clear value: +Inf, "no occluder".
  static const float* far_clear();

 private:
  const QueryDevice* device_;
  std::unique_ptr<QueryProgram> program_;
};

}  // namespace pn
