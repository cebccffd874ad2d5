// The physical reference's CPU definition, independent of rasterisation: for
// the surface point a camera pixel sees (ray_cast_surface_point, scene.h),
// the fraction of the light's sample points (scene/light_samples.h) that the
// point sees, by segment-versus-box tests.
// Beside it, what hard shadows from shadow maps may answer instead: a shadow
// map knows the scene only along the rays through its texel centres, so a
// receiver is tested against what the ray through its texel's centre sees.
// Cost: per pixel, samples x boxes segment tests, and samples x 1-4 light rays.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "core/image.h"
#include "scene/scene.h"

namespace pn {

// Whether the segment from `point` to `light` misses every box. It starts
// kSelfOffset world units from `point` toward `light`, so the face the point
// lies on hides it only when it faces away from the light (the start is then
// inside that face's box).
inline constexpr double kSelfOffset = 1e-5;
bool sees_point(const Scene& scene, const glm::dvec3& point, const glm::dvec3& light);

// Fraction of `lights` that `point` sees (1 for an empty list).
double visible_fraction(const Scene& scene, const glm::dvec3& point, const std::vector<glm::vec3>& lights);

// The answers the shadow-map test may give `point` for a point light at
// `scene.light_position` (with the centre's orientation and projection): for
// each texel within kTexelTie texels of the point's projection (float rounding
// of the projection may pick any of them), the depth of the nearest surface
// through the texel's centre (ray_cast_light_depth) against the point's light
// depth dP, occluded when depth < dP - bias; outside the map or behind the
// light, lit.
struct ShadowMapAnswers {
  bool lit = false, shadowed = false;
};
inline constexpr double kTexelTie = 1e-3;
ShadowMapAnswers shadow_map_answers(const Scene& scene, const glm::dvec3& point, double bias);

// Per pixel of a size x size screen (rows from the bottom, as GL reads them
// back), over light_sample_points(scene, samples_per_side).
struct VisibilityReference {
  Image fraction;  // the physical reference: the fraction of sample points the surface point sees; 1: no surface
  // The range nearest-texel hard shadows may give: per sample point, the exact
  // answer or any of its shadow_map_answers, counted low and high.
  Image lowest, highest;
  Image box;  // the box the pixel sees (SurfacePoint::box), -1 for none
};
VisibilityReference visibility_reference(const Scene& scene, int size, int samples_per_side, double bias);

}  // namespace pn
