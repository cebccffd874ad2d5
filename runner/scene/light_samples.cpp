#include "scene/light_samples.h"

#include <string>

#include "core/error.h"

namespace pn {

std::vector<glm::vec3> light_sample_points(const Scene& scene, int samples_per_side) {
  if (samples_per_side < 1 || samples_per_side > kMaxSamplesPerSide)
    throw Error("light samples per side " + std::to_string(samples_per_side) + ": expected 1 to " +
                std::to_string(kMaxSamplesPerSide));
  // The light's plane from its view: the inverse view's first two columns are its x and y axes in world space.
  const glm::dmat4 to_world = glm::inverse(glm::dmat4(scene.light_view()));
  const glm::dvec3 right(to_world[0]), up(to_world[1]), centre(scene.light_position);
  const double width = scene.light.width, n = samples_per_side;
  std::vector<glm::vec3> points;
  points.reserve(static_cast<size_t>(samples_per_side) * samples_per_side);
  for (int j = 0; j < samples_per_side; ++j)
    for (int i = 0; i < samples_per_side; ++i) {
      const double a = width * ((i + 0.5) / n - 0.5), b = width * ((j + 0.5) / n - 0.5);
      points.push_back(glm::vec3(centre + a * right + b * up));
    }
  return points;
}

}  // namespace pn
