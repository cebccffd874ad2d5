#include "passes/physical_reference_pass.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <string>

#include "core/error.h"
#include "core/format.h"
#include "gl/texture.h"
#include "passes/scene_draw.h"
#include "scene/light_samples.h"

namespace pn {

PhysicalReferenceRenderer::PhysicalReferenceRenderer(const Context& context, const SourceTree& tree)
    : context_(&context), shadow_map_(context, tree), program_(link_raster_pass(context, tree, "passes/hard_shadow")) {}

GlObject PhysicalReferenceRenderer::render(const Scene& scene, int screen_size, int samples_per_side,
                                           float bias) const {
  if (screen_size < 1) throw Error("screen size " + std::to_string(screen_size) + ": expected at least 1");
  if (!std::isfinite(bias) || bias < 0)
    throw Error("shadow bias " + format_number("%g", bias) + ": expected a finite number >= 0");
  const std::vector<glm::vec3> points = light_sample_points(scene, samples_per_side);  // validates the count

  struct {
    float camera[16], light_view[16], light_projection[16];
    float map_size, bias, divisor, padding;
  } block{};
  const glm::mat4 camera = scene.camera_projection() * scene.camera_view();
  std::copy_n(glm::value_ptr(camera), 16, block.camera);
  block.map_size = static_cast<float>(scene.light.map_size);
  block.bias = bias;

  const auto& gl = context_->gl();
  // The count before the first pass: 0 everywhere.
  GlObject count = make_float_texture(*context_, screen_size, screen_size, 1);
  const float zero = 0.0f;
  gl.ClearTexImage(count.id(), 0, GL_RED, GL_FLOAT, &zero);

  const float no_surface[4] = {1, 0, 0, 0};  // the last pass leaves 1 where no surface is seen
  Scene sample = scene;
  for (size_t k = 0; k < points.size(); ++k) {
    sample.light_position = points[k];
    const GlObject shadow_map = shadow_map_.render(sample);
    const glm::mat4 view = sample.light_view(), projection = sample.light_projection();
    std::copy_n(glm::value_ptr(view), 16, block.light_view);
    std::copy_n(glm::value_ptr(projection), 16, block.light_projection);
    // Counts are integers, exact in float; one division on the last pass makes the fraction (n / n is 1).
    block.divisor = k + 1 == points.size() ? static_cast<float>(points.size()) : 1.0f;
    gl.BindTextureUnit(1, shadow_map.id());
    gl.BindTextureUnit(2, count.id());
    GlObject next = draw_scene(*context_, program_, scene, screen_size, 1, no_surface, &block, sizeof block);
    gl.BindTextureUnit(1, 0);
    gl.BindTextureUnit(2, 0);
    count = std::move(next);
  }
  context_->throw_if_gl_error("physical reference of scene '" + scene.name + "'");
  return count;
}

}  // namespace pn
