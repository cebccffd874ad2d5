#include "pass_runners/shadow_map_pass.h"

#include <limits>

#include "gl/query_device_gl.h"
#include "gl/std140.h"
#include "pass_runners/scene_draw.h"

namespace pn::glsl {
#include "passes/shadow_depth.h"
PN_STD140_SIZE(PnShadowDepthParams, 128);
PN_STD140_OFFSET(PnShadowDepthParams, lightProjection, 64);
}  // namespace pn::glsl

namespace pn {

ShadowMapRenderer::ShadowMapRenderer(const QueryDevice& device, const SourceTree& tree)
    : device_(&device),
      program_(device.compile_raster(tree, "passes/shadow_depth.vert", "passes/shadow_depth.frag", TexelFormat::r32f)) {}

namespace {
glsl::PnShadowDepthParams light_block(const MapLight& light) {
  return {glsl::std140_mat4(light.view), glsl::std140_mat4(light.projection)};
}
}  // namespace

const float* ShadowMapRenderer::far_clear() {
  static const float far[4] = {std::numeric_limits<float>::infinity(), 0, 0, 0};
  return far;
}

std::unique_ptr<DeviceTexture> ShadowMapRenderer::render_texture(const Scene& scene, const MapLight& light) const {
  const glsl::PnShadowDepthParams block = light_block(light);
  return device_->draw_triangles(*program_, scene.triangles(), light.light.map_size, far_clear(),
                                 {{}, {}, {}, query_block(block)});
}

FloatTexture ShadowMapRenderer::render(const Scene& scene, const MapLight& light) const {
  return take_float_texture(render_texture(scene, light));
}

void ShadowMapRenderer::draw(const Scene& scene, const SceneGeometry& geometry, const DeviceRasterTarget& target,
                             const std::vector<VertexRun>& runs, const std::vector<TexelRect>& rects) const {
  const glsl::PnShadowDepthParams block = light_block(scene.map_light());
  device_->draw(*program_, geometry.vertices(), runs, target, rects, {{}, {}, {}, query_block(block)});
}

}  // namespace pn
