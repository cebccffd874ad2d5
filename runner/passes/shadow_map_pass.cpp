#include "passes/shadow_map_pass.h"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <limits>

#include "passes/scene_draw.h"
#include "gl/texture.h"

namespace pn {

ShadowMapRenderer::ShadowMapRenderer(const Context& context, const SourceTree& tree)
    : context_(&context), program_(link_raster_pass(context, tree, "passes/shadow_depth")) {}

GlObject ShadowMapRenderer::render(const Scene& scene) const {
  struct {
    float view[16], projection[16];
  } block{};
  const glm::mat4 view = scene.light_view(), projection = scene.light_projection();
  std::copy_n(glm::value_ptr(view), 16, block.view);
  std::copy_n(glm::value_ptr(projection), 16, block.projection);
  const float far[4] = {std::numeric_limits<float>::infinity(), 0, 0, 0};
  return draw_scene(*context_, program_, scene, scene.light.map_size, 1, far, &block, sizeof block);
}

}  // namespace pn
