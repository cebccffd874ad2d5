#include "pass_runners/shadow_map_pass.h"

#include <limits>

#include "core/error.h"
#include "gl/query_device_gl.h"
#include "gl/std140.h"
#include "pass_runners/scene_draw.h"

namespace pn::glsl {
#include "passes/shadow_depth.h"
PN_STD140_SIZE(PnShadowDepthParams, 128);
PN_STD140_OFFSET(PnShadowDepthParams, lightProjection, 64);
}  // namespace pn::glsl

namespace pn {

namespace {
glsl::PnShadowDepthParams light_block(const MapLight& light) {
  return {glsl::std140_mat4(light.view), glsl::std140_mat4(light.projection)};
}

const char* fragment_pass(MapLayer layer) {
  switch (layer) {
    case MapLayer::peeled: return "passes/shadow_depth_peel.frag";
    case MapLayer::back_faces: return "passes/shadow_depth_back.frag";
    case MapLayer::first: break;
  }
  return "passes/shadow_depth.frag";
}
}  // namespace

const char* map_layer_name(MapLayer layer) {
  switch (layer) {
    case MapLayer::peeled: return "peeled";
    case MapLayer::back_faces: return "back-faces";
    case MapLayer::first: break;
  }
  return "first";
}

ShadowMapRenderer::ShadowMapRenderer(const QueryDevice& device, const SourceTree& tree, MapLayer layer)
    : device_(&device),
      layer_(layer),
      program_(device.compile_raster(tree, "passes/shadow_depth.vert", fragment_pass(layer), TexelFormat::r32f)) {}

double ShadowMapRenderer::peel_margin() { return PN_SHADOW_DEPTH_PEEL_MARGIN; }

PassResources ShadowMapRenderer::resources(const QueryBlock& block, const DeviceTexture* first) const {
  PassResources out{{}, {}, {}, block};
  if (layer_ != MapLayer::peeled) return out;
  if (first == nullptr) throw Error("shadow map: a peeled layer needs the map it lies behind");
  out.add_textures({{PN_SHADOW_DEPTH_FIRST_LAYER_BINDING, *first}});
  return out;
}

const float* ShadowMapRenderer::far_clear() {
  static const float far[4] = {std::numeric_limits<float>::infinity(), 0, 0, 0};
  return far;
}

std::unique_ptr<DeviceTexture> ShadowMapRenderer::render_texture(const Scene& scene, const MapLight& light,
                                                                 const DeviceTexture* first) const {
  const glsl::PnShadowDepthParams block = light_block(light);
  return device_->draw_triangles(*program_, scene.triangles(), light.light.map_size, far_clear(),
                                 resources(query_block(block), first));
}

FloatTexture ShadowMapRenderer::render(const Scene& scene, const MapLight& light) const {
  return take_float_texture(render_texture(scene, light));
}

void ShadowMapRenderer::draw(const Scene& scene, const SceneGeometry& geometry, const DeviceRasterTarget& target,
                             const std::vector<VertexRun>& runs, const std::vector<TexelRect>& rects,
                             const DeviceTexture* first) const {
  const glsl::PnShadowDepthParams block = light_block(scene.map_light());
  device_->draw(*program_, geometry.vertices(), runs, target, rects, resources(query_block(block), first));
}

}  // namespace pn
