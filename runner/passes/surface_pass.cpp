#include "passes/surface_pass.h"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <string>

#include "core/error.h"
#include "passes/scene_draw.h"

namespace pn {

SurfaceRenderer::SurfaceRenderer(const Context& context, const SourceTree& tree)
    : context_(&context), program_(link_raster_pass(context, tree, "passes/surface")) {}

GlObject SurfaceRenderer::render(const Scene& scene, int screen_size) const {
  if (screen_size < 1) throw Error("screen size " + std::to_string(screen_size) + ": expected at least 1");
  if (scene.boxes.empty()) throw Error("scene '" + scene.name + "': expected a ground box (boxes[0])");
  struct {
    float camera[16];
    float camera_position[4], light_position[4], ground_lo[4], ground_hi[4], ground_albedo[4], box_albedo[4];
  } block{};
  const glm::mat4 camera = scene.camera_projection() * scene.camera_view();
  std::copy_n(glm::value_ptr(camera), 16, block.camera);
  const auto put = [](float* out, const glm::vec3& v) { std::copy_n(glm::value_ptr(v), 3, out); };
  put(block.camera_position, glm::vec3(glm::inverse(scene.camera_view())[3]));
  put(block.light_position, scene.light_position);
  put(block.ground_lo, scene.boxes[0].lo);
  put(block.ground_hi, scene.boxes[0].hi);
  put(block.ground_albedo, kGroundAlbedo);
  put(block.box_albedo, kBoxAlbedo);
  const float nothing[4] = {0, 0, 0, 0};
  return draw_scene(*context_, program_, scene, screen_size, 4, nothing, &block, sizeof block);
}

}  // namespace pn
