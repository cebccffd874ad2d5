#include "scene/visibility_reference.h"

#include <algorithm>
#include <cmath>

#include "scene/light_samples.h"

namespace pn {

bool sees_point(const Scene& scene, const glm::dvec3& point, const glm::dvec3& light) {
  const glm::dvec3 to_light = light - point;
  const double length = glm::length(to_light);
  if (length <= kSelfOffset) return true;
  const glm::dvec3 start = point + to_light * (kSelfOffset / length);
  return std::none_of(scene.boxes.begin(), scene.boxes.end(),
                      [&](const Box& b) { return box_entry(b, start, light - start, 1.0).has_value(); });
}

double visible_fraction(const Scene& scene, const glm::dvec3& point, const std::vector<glm::vec3>& lights) {
  if (lights.empty()) return 1.0;
  int seen = 0;
  for (const glm::vec3& light : lights) seen += sees_point(scene, point, glm::dvec3(light)) ? 1 : 0;
  return static_cast<double>(seen) / static_cast<double>(lights.size());
}

ShadowMapAnswers shadow_map_answers(const Scene& scene, const glm::dvec3& point, double bias) {
  const Receiver p = project_to_light(scene, point);
  ShadowMapAnswers answers;
  if (!p.valid) {
    answers.lit = true;
    return answers;
  }
  const double n = scene.light.map_size;
  for (double du : {-kTexelTie, kTexelTie})
    for (double dv : {-kTexelTie, kTexelTie}) {
      const double tu = std::floor(p.u + du), tv = std::floor(p.v + dv);
      const bool inside = tu >= 0 && tv >= 0 && tu < n && tv < n;
      if (inside && ray_cast_light_depth(scene, static_cast<int>(tu), static_cast<int>(tv)) < p.depth - bias)
        answers.shadowed = true;
      else
        answers.lit = true;
    }
  return answers;
}

VisibilityReference visibility_reference(const Scene& scene, int size, int samples_per_side, double bias) {
  const std::vector<glm::vec3> lights = light_sample_points(scene, samples_per_side);
  std::vector<Scene> moved(lights.size(), scene);  // one point light per sample, for its shadow map
  for (size_t k = 0; k < lights.size(); ++k) moved[k].light_position = lights[k];
  VisibilityReference out{Image(size, size, 1, 1.0f), Image(size, size, 1, 1.0f), Image(size, size, 1, 1.0f),
                          Image(size, size, 1, -1.0f)};
  const double count = static_cast<double>(lights.size());
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const auto surface = ray_cast_surface_point(scene, x, y, size);
      if (!surface) continue;
      int seen = 0, lowest = 0, highest = 0;
      for (size_t k = 0; k < lights.size(); ++k) {
        const bool exact = sees_point(scene, surface->position, glm::dvec3(lights[k]));
        const ShadowMapAnswers raster = shadow_map_answers(moved[k], surface->position, bias);
        seen += exact;
        lowest += exact && !raster.shadowed;
        highest += exact || raster.lit;
      }
      out.fraction.at(x, y) = static_cast<float>(seen / count);
      out.lowest.at(x, y) = static_cast<float>(lowest / count);
      out.highest.at(x, y) = static_cast<float>(highest / count);
      out.box.at(x, y) = static_cast<float>(surface->box);
    }
  return out;
}

}  // namespace pn
