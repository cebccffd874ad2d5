// The analytic visibility test of the box scenes, independent of any shadow
// map and of Embree: whether a surface point sees a point on the light, by
// segment-versus-box tests (box_entry, scene.h). The ray-traced truth's check
// (check/truth_check.cpp) holds the truth to it on the very same segments.
// Cost: one slab test per box.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace pn {

// Whether the segment from `point` to `light` misses every box. It starts
// kSelfOffset world units from `point` toward `light`, so the face the point
// lies on hides it only when it faces away from the light (the start is then
// inside that face's box).
inline constexpr double kSelfOffset = 1e-5;
bool sees_point(const Scene& scene, const glm::dvec3& point, const glm::dvec3& light);

}  // namespace pn
