// A directional light's view of a scene's bounds: the sun's whole-scene map
// (scene.cpp's light_by_sun) and every cascade (cascades/cascade_fit.h) look
// through the same view, so light-space positions agree between them.
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace pn {

// The eight corners of the box [lo, hi].
std::vector<glm::dvec3> box_corners(const glm::vec3& lo, const glm::vec3& hi);

// The light's view: looking along `direction` (normalised inside) from a point that is
// fixed in the world — on the line through the origin, one unit before the nearest corner of
// the scene's bounds — so that every point of the scene has a linear light depth >= 1 and
// a world point's light-space (x, y) never depends on the camera.
glm::mat4 directional_light_view(const glm::vec3& direction, const glm::vec3& scene_lo, const glm::vec3& scene_hi);

}  // namespace pn
