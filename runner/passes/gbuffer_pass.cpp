#include "passes/gbuffer_pass.h"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>

#include "passes/scene_draw.h"

namespace pn {

GBufferRenderer::GBufferRenderer(const Context& context, const SourceTree& tree)
    : context_(&context), program_(link_raster_pass(context, tree, "passes/gbuffer")) {}

GlObject GBufferRenderer::render(const Scene& scene, int screen_size, float normal_offset_texels) const {
  struct {
    float camera[16], light_view[16], light_projection[16];
    float camera_position[4];
    float map_size, normal_offset, texel_per_depth, padding;
  } block{};
  const glm::mat4 camera = scene.camera_projection() * scene.camera_view();
  const glm::mat4 view = scene.light_view(), projection = scene.light_projection();
  std::copy_n(glm::value_ptr(camera), 16, block.camera);
  std::copy_n(glm::value_ptr(view), 16, block.light_view);
  std::copy_n(glm::value_ptr(projection), 16, block.light_projection);
  block.map_size = static_cast<float>(scene.light.map_size);
  for (int i = 0; i < 3; ++i) block.camera_position[i] = fixtures::kCameraPosition[i];
  block.normal_offset = normal_offset_texels;
  block.texel_per_depth =
      static_cast<float>(scene.light.near_plane_width() / scene.light.near_plane / scene.light.map_size);
  const float nothing[4] = {0, 0, 0, 0};
  return draw_scene(*context_, program_, scene, screen_size, 4, nothing, &block, sizeof block);
}

}  // namespace pn
