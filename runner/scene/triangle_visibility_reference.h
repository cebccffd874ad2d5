// The model scenes' independent caster, as visibility_reference.h's slab
// tests are the box scenes': segments against every triangle of
// Scene::triangles(), in double (Möller–Trumbore, no acceleration structure,
// no watertightness), for the ray-traced truth's check on the spider and the
// city (check/truth_check.cpp). Where a float tracer and this one may differ —
// a segment through a triangle's edge or vertex, or along its plane — is a
// graze (segment_grazes_triangles), which the check counts apart.
// Cost: every triangle per segment.
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

namespace pn {

struct TriangleHit {
  double t = 0.0;          // along the segment, origin + t · direction
  std::size_t triangle = 0;  // index into the triangles (vertices 3 · triangle ...)
};

// The nearest triangle the segment origin + t · direction, 0 < t <= t_max, meets (3 vertices a
// triangle; a degenerate one is never met).
std::optional<TriangleHit> nearest_triangle(const std::vector<glm::vec3>& triangles, const glm::dvec3& origin,
                                            const glm::dvec3& direction, double t_max);

// Whether any triangle meets the segment at 0 < t < t_max.
bool segment_blocked(const std::vector<glm::vec3>& triangles, const glm::dvec3& origin, const glm::dvec3& direction,
                     double t_max);

// Whether the segment from `from` to `to` passes within `band` (world units) of a triangle's
// boundary where it crosses the triangle's plane, or runs within `band` of a triangle's plane
// (nearly along it) or starts within `band` of a triangle: where rounding may decide a hit.
bool segment_grazes_triangles(const std::vector<glm::vec3>& triangles, const glm::dvec3& from, const glm::dvec3& to,
                              double band);

}  // namespace pn
