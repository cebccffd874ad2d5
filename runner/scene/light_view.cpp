#include "scene/light_view.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/format.h"

namespace pn {

std::vector<glm::dvec3> box_corners(const glm::vec3& lo, const glm::vec3& hi) {
  std::vector<glm::dvec3> out;
  for (int c = 0; c < 8; ++c) out.push_back({(c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z});
  return out;
}

glm::mat4 directional_light_view(const glm::vec3& direction, const glm::vec3& scene_lo, const glm::vec3& scene_hi) {
  const double length = glm::length(glm::dvec3(direction));
  if (!(length > 0) || !std::isfinite(length))
    throw Error("light direction (" + format_number("%g", direction.x) + ", " + format_number("%g", direction.y) + ", " +
                format_number("%g", direction.z) + "): expected a finite, non-zero vector");
  const glm::dvec3 d = glm::dvec3(direction) / length;
  double nearest = INFINITY;
  for (const glm::dvec3& c : box_corners(scene_lo, scene_hi)) nearest = std::min(nearest, glm::dot(c, d));
  const glm::dvec3 eye = d * (nearest - 1.0);
  const glm::dvec3 up = std::fabs(d.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
  return glm::mat4(glm::lookAt(eye, eye + d, up));
}

}  // namespace pn
