#include "passes/shadow_map_pass.h"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <limits>

#include "passes/scene_draw.h"
#include "gl/texture.h"
#include "shader/flatten.h"

namespace pn {

ShadowMapRenderer::ShadowMapRenderer(const Context& context, const SourceTree& tree) : context_(&context) {
  const ShaderSource vertex = standalone_source(flatten(tree, "passes/shadow_depth.vert"), Target::gl450);
  const ShaderSource fragment = standalone_source(flatten(tree, "passes/shadow_depth.frag"), Target::gl450);
  program_ = link_program(context, "passes/shadow_depth", {&vertex, &fragment});
}

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
