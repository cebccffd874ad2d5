#include "passes/shadow_map_pass.h"

#include <limits>

#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "passes/scene_draw.h"

namespace pn::glsl {
#include "passes/shadow_depth.h"
PN_STD140_SIZE(PnShadowDepthParams, 128);
PN_STD140_OFFSET(PnShadowDepthParams, lightProjection, 64);
}  // namespace pn::glsl

namespace pn {

ShadowMapRenderer::ShadowMapRenderer(const Context& context, const SourceTree& tree)
    : context_(&context), program_(link_raster_pass(context, tree, "passes/shadow_depth")) {}

namespace {
glsl::PnShadowDepthParams light_block(const MapLight& light) {
  return {glsl::std140_mat4(light.view), glsl::std140_mat4(light.projection)};
}
}  // namespace

const float* ShadowMapRenderer::far_clear() {
  static const float far[4] = {std::numeric_limits<float>::infinity(), 0, 0, 0};
  return far;
}

FloatTexture ShadowMapRenderer::render(const Scene& scene, const MapLight& light) const {
  PassBindings bind(*context_);
  bind.uniform(light_block(light));
  return draw_scene(*context_, program_, scene, light.light.map_size, 1, far_clear());
}

void ShadowMapRenderer::draw(const Scene& scene, const SceneGeometry& geometry, const RasterTarget& target,
                             const std::vector<VertexRun>& runs, const std::vector<TexelRect>& rects) const {
  PassBindings bind(*context_);
  bind.uniform(light_block(scene.map_light()));
  target.draw(program_, geometry, runs, rects);
}

}  // namespace pn
