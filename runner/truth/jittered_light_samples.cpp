#include "truth/jittered_light_samples.h"

#include <cmath>

#include "core/integer_hash.h"

namespace pn {

double sample_jitter(std::uint32_t seed, int x, int y, int sample, int axis) {
  // Chained, so that every input moves every output bit.
  std::uint32_t h = integer_hash(seed ^ 0x9e3779b9U);
  h = integer_hash(h ^ static_cast<std::uint32_t>(x));
  h = integer_hash(h ^ static_cast<std::uint32_t>(y));
  h = integer_hash(h ^ static_cast<std::uint32_t>(sample));
  h = integer_hash(h ^ static_cast<std::uint32_t>(axis));
  return static_cast<double>(h >> 8) * (1.0 / 16777216.0);
}

LightFrame light_frame(const Scene& scene) {
  // The inverse light view's first two columns are the light plane's x and y axes in world space.
  const glm::dmat4 to_world = glm::inverse(glm::dmat4(scene.light_view()));
  LightFrame light{glm::dvec3(scene.light_position), glm::normalize(glm::dvec3(to_world[0])),
                   glm::normalize(glm::dvec3(to_world[1])), scene.light.width};
  if (scene.sun) {
    light.directional = true;
    light.towards = -glm::normalize(glm::dvec3(scene.sun->direction));
    light.tan_half_angle = std::tan(0.5 * scene.sun->angular_diameter_radians);
    const auto [lo, hi] = scene.bounds();
    light.distance = 4.0 * glm::length(glm::dvec3(hi) - glm::dvec3(lo)) + 1.0;
    light.centre = light.distance * light.towards;
  }
  return light;
}

bool faces_light(const LightFrame& light, const glm::dvec3& position, const glm::dvec3& normal) {
  return glm::dot(normal, light.directional ? light.towards : light.centre - position) > 0.0;
}

std::vector<glm::dvec3> jittered_sun_points(const LightFrame& light, int samples_per_side, std::uint32_t seed, int x,
                                            int y, const glm::dvec3& receiver) {
  const double n = samples_per_side, quarter_pi = 0.78539816339744831;
  std::vector<glm::dvec3> points;
  points.reserve(static_cast<size_t>(samples_per_side) * samples_per_side);
  for (int j = 0; j < samples_per_side; ++j)
    for (int i = 0; i < samples_per_side; ++i) {
      const int k = j * samples_per_side + i;
      // Concentric map of [-1, 1]² onto the unit disc (Shirley and Chiu 1997).
      const double a = 2.0 * (i + sample_jitter(seed, x, y, k, 0)) / n - 1.0;
      const double b = 2.0 * (j + sample_jitter(seed, x, y, k, 1)) / n - 1.0;
      double r = 0, phi = 0;
      if (a == 0 && b == 0) r = 0, phi = 0;
      else if (std::fabs(a) > std::fabs(b)) r = a, phi = quarter_pi * (b / a);
      else r = b, phi = 2 * quarter_pi - quarter_pi * (a / b);
      const glm::dvec3 direction = light.towards + light.tan_half_angle * r * (std::cos(phi) * light.right + std::sin(phi) * light.up);
      points.push_back(receiver + light.distance * glm::normalize(direction));
    }
  return points;
}

std::vector<glm::dvec3> jittered_light_samples(const LightFrame& light, int samples_per_side, std::uint32_t seed, int x,
                                               int y) {
  const double n = samples_per_side;
  std::vector<glm::dvec3> points;
  points.reserve(static_cast<size_t>(samples_per_side) * samples_per_side);
  for (int j = 0; j < samples_per_side; ++j)
    for (int i = 0; i < samples_per_side; ++i) {
      const int k = j * samples_per_side + i;
      const double a = light.width * ((i + sample_jitter(seed, x, y, k, 0)) / n - 0.5);
      const double b = light.width * ((j + sample_jitter(seed, x, y, k, 1)) / n - 0.5);
      points.push_back(light.centre + a * light.right + b * light.up);
    }
  return points;
}

}  // namespace pn
