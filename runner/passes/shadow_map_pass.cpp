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

GlObject ShadowMapRenderer::render(const Scene& scene) const {
  const glsl::PnShadowDepthParams block{glsl::std140_mat4(scene.light_view()),
                                        glsl::std140_mat4(scene.light_projection())};
  const float far[4] = {std::numeric_limits<float>::infinity(), 0, 0, 0};
  PassBindings bind(*context_);
  bind.uniform(block);
  return draw_scene(*context_, program_, scene, scene.light.map_size, 1, far);
}

}  // namespace pn
