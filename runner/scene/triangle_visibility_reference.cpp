#include "scene/triangle_visibility_reference.h"

#include <algorithm>
#include <cmath>

namespace pn {
namespace {

struct Triangle {
  glm::dvec3 a, b, c;
};

Triangle triangle_at(const std::vector<glm::vec3>& triangles, std::size_t i) {
  return {glm::dvec3(triangles[3 * i]), glm::dvec3(triangles[3 * i + 1]), glm::dvec3(triangles[3 * i + 2])};
}

// Möller–Trumbore: the t at which origin + t · direction meets the triangle, if it does.
std::optional<double> meets(const Triangle& tri, const glm::dvec3& origin, const glm::dvec3& direction) {
  const glm::dvec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a, p = glm::cross(direction, e2);
  const double det = glm::dot(e1, p);
  if (det == 0.0 || !std::isfinite(det)) return std::nullopt;  // along the plane, or degenerate
  const glm::dvec3 s = origin - tri.a;
  const double u = glm::dot(s, p) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(direction, q) / det;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  return glm::dot(e2, q) / det;
}

// The point of the triangle nearest p (Ericson, Real-Time Collision Detection §5.1.5).
glm::dvec3 nearest_on_triangle(const glm::dvec3& p, const Triangle& t) {
  const glm::dvec3 ab = t.b - t.a, ac = t.c - t.a, ap = p - t.a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return t.a;
  const glm::dvec3 bp = p - t.b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return t.b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return t.a + ab * (d1 / (d1 - d3));
  const glm::dvec3 cp = p - t.c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return t.c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return t.a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return t.b + (t.c - t.b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denominator = va + vb + vc;
  return t.a + ab * (vb / denominator) + ac * (vc / denominator);
}

// The distance between the segments p1q1 and p2q2 (Ericson §5.1.9).
double segment_distance(const glm::dvec3& p1, const glm::dvec3& q1, const glm::dvec3& p2, const glm::dvec3& q2) {
  const glm::dvec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
  double s = 0.0, t = 0.0;
  if (a <= 0.0 && e <= 0.0) return glm::length(r);
  if (a <= 0.0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = glm::dot(d1, r);
    if (e <= 0.0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = glm::dot(d1, d2), denominator = a * e - b * b;
      s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) t = 0.0, s = std::clamp(-c / a, 0.0, 1.0);
      else if (t > 1.0) t = 1.0, s = std::clamp((b - c) / a, 0.0, 1.0);
    }
  }
  return glm::length((p1 + d1 * s) - (p2 + d2 * t));
}

// How far inside the triangle a point of its plane lies: the least distance to its three edge
// lines when inside (<= 0 outside).
double depth_inside(const glm::dvec3& x, const Triangle& t, const glm::dvec3& unit_normal) {
  double least = INFINITY;
  for (const auto& [p, q] : {std::pair{t.a, t.b}, std::pair{t.b, t.c}, std::pair{t.c, t.a}}) {
    const glm::dvec3 inward = glm::normalize(glm::cross(unit_normal, q - p));  // counter-clockwise about the normal
    least = std::min(least, glm::dot(x - p, inward));
  }
  return least;
}

}  // namespace

std::optional<TriangleHit> nearest_triangle(const std::vector<glm::vec3>& triangles, const glm::dvec3& origin,
                                            const glm::dvec3& direction, double t_max) {
  std::optional<TriangleHit> best;
  for (std::size_t i = 0; i < triangles.size() / 3; ++i) {
    const std::optional<double> t = meets(triangle_at(triangles, i), origin, direction);
    if (t && *t > 0.0 && *t <= t_max && (!best || *t < best->t)) best = TriangleHit{*t, i};
  }
  return best;
}

bool segment_blocked(const std::vector<glm::vec3>& triangles, const glm::dvec3& origin, const glm::dvec3& direction,
                     double t_max) {
  for (std::size_t i = 0; i < triangles.size() / 3; ++i) {
    const std::optional<double> t = meets(triangle_at(triangles, i), origin, direction);
    if (t && *t > 0.0 && *t < t_max) return true;
  }
  return false;
}

bool segment_grazes_triangles(const std::vector<glm::vec3>& triangles, const glm::dvec3& from, const glm::dvec3& to,
                              double band) {
  const glm::dvec3 lo = glm::min(from, to) - band, hi = glm::max(from, to) + band;
  for (std::size_t i = 0; i < triangles.size() / 3; ++i) {
    const Triangle t = triangle_at(triangles, i);
    if (glm::any(glm::lessThan(glm::max(glm::max(t.a, t.b), t.c), lo)) ||
        glm::any(glm::greaterThan(glm::min(glm::min(t.a, t.b), t.c), hi)))
      continue;  // the triangle's box misses the segment's grown box
    const glm::dvec3 normal = glm::cross(t.b - t.a, t.c - t.a);
    const double area = glm::length(normal);
    if (!(area > 0.0)) continue;  // degenerate: never met
    const glm::dvec3 n = normal / area;
    const double df = glm::dot(n, from - t.a), dt = glm::dot(n, to - t.a);
    const bool crosses = df * dt < 0.0;
    const glm::dvec3 x = crosses ? from + (to - from) * (df / (df - dt)) : from;  // where it crosses the plane
    // A clear crossing: both ends more than `band` off the plane on either side, through a point
    // more than `band` inside every edge: any caster meets it.
    if (crosses && std::fabs(df) > band && std::fabs(dt) > band && depth_inside(x, t, n) > band) continue;
    // Otherwise: a graze when the segment passes within `band` of the triangle (its ends, its edges,
    // or where it crosses the plane).
    double distance = std::min(glm::length(from - nearest_on_triangle(from, t)),
                               glm::length(to - nearest_on_triangle(to, t)));
    distance = std::min({distance, segment_distance(from, to, t.a, t.b), segment_distance(from, to, t.b, t.c),
                         segment_distance(from, to, t.c, t.a)});
    if (crosses) distance = std::min(distance, glm::length(x - nearest_on_triangle(x, t)));
    if (distance <= band) return true;
  }
  return false;
}

}  // namespace pn
