#include "scene/visibility_reference.h"

#include <algorithm>

namespace pn {

bool sees_point(const Scene& scene, const glm::dvec3& point, const glm::dvec3& light) {
  const glm::dvec3 to_light = light - point;
  const double length = glm::length(to_light);
  if (length <= kSelfOffset) return true;
  const glm::dvec3 start = point + to_light * (kSelfOffset / length);
  return std::none_of(scene.boxes.begin(), scene.boxes.end(),
                      [&](const Box& b) { return box_entry(b, start, light - start, 1.0).has_value(); });
}

}  // namespace pn
