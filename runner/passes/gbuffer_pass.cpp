#include "passes/gbuffer_pass.h"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>

#include "passes/scene_draw.h"

namespace pn {

GBufferRenderer::GBufferRenderer(const Context& context, const SourceTree& tree)
    : context_(&context), program_(link_raster_pass(context, tree, "passes/gbuffer")) {}

GlObject GBufferRenderer::render(const Scene& scene, int screen_size) const {
  struct {
    float camera[16], light_view[16], light_projection[16];
    float map_size, padding[3];
  } block{};
  const glm::mat4 camera = scene.camera_projection() * scene.camera_view();
  const glm::mat4 view = scene.light_view(), projection = scene.light_projection();
  std::copy_n(glm::value_ptr(camera), 16, block.camera);
  std::copy_n(glm::value_ptr(view), 16, block.light_view);
  std::copy_n(glm::value_ptr(projection), 16, block.light_projection);
  block.map_size = static_cast<float>(scene.light.map_size);
  const float nothing[4] = {0, 0, 0, 0};
  return draw_scene(*context_, program_, scene, screen_size, 4, nothing, &block, sizeof block);
}

}  // namespace pn
