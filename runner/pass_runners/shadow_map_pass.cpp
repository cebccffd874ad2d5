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

// Each layer's name (the options') and fragment stage.
struct LayerPass {
  MapLayer layer;
  const char* name;
  const char* fragment;
};
constexpr LayerPass kLayerPasses[] = {{MapLayer::first, "first", "passes/shadow_depth.frag"},
                                      {MapLayer::peeled, "peeled", "passes/shadow_depth_peel.frag"},
                                      {MapLayer::back_faces, "back-faces", "passes/shadow_depth_back.frag"}};

const LayerPass& layer_pass(MapLayer layer) {
  for (const LayerPass& p : kLayerPasses)
    if (p.layer == layer) return p;
  return kLayerPasses[0];
}
}  // namespace

const char* map_layer_name(MapLayer layer) { return layer_pass(layer).name; }

ShadowMapRenderer::ShadowMapRenderer(const QueryDevice& device, const SourceTree& tree, MapLayer layer)
    : device_(&device),
      layer_(layer),
      program_(device.compile_raster(tree, "passes/shadow_depth.vert", layer_pass(layer).fragment, TexelFormat::r32f)) {}

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
