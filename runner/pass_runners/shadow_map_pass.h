// Runner side of glsl/passes/shadow_depth.vert/.frag: renders a scene's
// shadow map of linear light depth (SPEC §4.7 Step 1) into an R32F texture,
// +Inf where no surface is seen (SPEC §3: no occluder) — or its second layer
// (issue 42: shadow_depth_peel.frag, shadow_depth_back.frag), the surface
// behind it that back-projection's slabs read.
#pragma once

#include <memory>

#include "device/query_device.h"
#include "gl/texture.h"
#include "pass_runners/scene_draw.h"
#include "scene/scene.h"
#include "shader/source_tree.h"

namespace pn {

// Which layer of the scene a renderer draws: the map (the nearest surface), or a second layer —
// by depth peeling (the nearest surface behind the map's texel; needs the map) or from back
// faces (the nearest surface facing away from the light).
enum class MapLayer { first, peeled, back_faces };

// "first", "peeled", "back-faces": the names the options use.
const char* map_layer_name(MapLayer layer);

class ShadowMapRenderer {
 public:
  ShadowMapRenderer(const QueryDevice& device, const SourceTree& tree, MapLayer layer = MapLayer::first);
  MapLayer layer() const { return layer_; }

  // N×N R32F texture on the device, N = light.light.map_size (the scene's light, or another view
  // and projection: a cascade's); rows from the framebuffer's bottom. Any executor. `first`: the
  // map drawn through the same light, which a peeled layer reads (Error without it).
  std::unique_ptr<DeviceTexture> render_texture(const Scene& scene, const MapLight& light,
                                                const DeviceTexture* first = nullptr) const;
  // The same as a GL texture (the device is a GL context).
  FloatTexture render(const Scene& scene) const { return render(scene, scene.map_light()); }
  FloatTexture render(const Scene& scene, const MapLight& light) const;

  // Into a kept N×N R32F target: `runs` of `geometry` (the scene's vertices) with the scene's
  // light, within `rects` (everywhere for none), over what the target holds. What the caches draw.
  void draw(const Scene& scene, const SceneGeometry& geometry, const DeviceRasterTarget& target,
            const std::vector<VertexRun>& runs, const std::vector<TexelRect>& rects = {},
            const DeviceTexture* first = nullptr) const;
  // The map's clear value: +Inf, "no occluder".
  static const float* far_clear();
  // Depth peeling's margin, a share of the first layer's depth (PN_SHADOW_DEPTH_PEEL_MARGIN).
  static double peel_margin();

 private:
  PassResources resources(const QueryBlock& block, const DeviceTexture* first) const;

  const QueryDevice* device_;
  MapLayer layer_;
  std::unique_ptr<QueryProgram> program_;
};

}  // namespace pn
