// The analytic segment test, by hand on a table top floating under the light
// (hand_scene.h): which light points a point under, beside and far from the
// table sees, and the camera ray the G-buffer's reference casts.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "hand_scene.h"
#include "scene/visibility_reference.h"

using pn::test::table_scene;

namespace {

// The centres of a 4x4 grid of cells over the table scene's light of width 2 at height 20:
// x, z at -0.75, -0.25, 0.25, 0.75.
std::vector<glm::dvec3> light_grid() {
  std::vector<glm::dvec3> out;
  for (double x : {-0.75, -0.25, 0.25, 0.75})
    for (double z : {-0.75, -0.25, 0.25, 0.75}) out.push_back({x, 20.0, z});
  return out;
}

double seen_fraction(const pn::Scene& scene, const glm::dvec3& point, const std::vector<glm::dvec3>& lights) {
  int seen = 0;
  for (const glm::dvec3& light : lights) seen += pn::sees_point(scene, point, light) ? 1 : 0;
  return static_cast<double>(seen) / static_cast<double>(lights.size());
}

}  // namespace

TEST_CASE("segment tests: the table's top sees the light, its underside and the ground under it do not") {
  const pn::Scene scene = table_scene();
  const glm::dvec3 light(0.25, 20.0, -0.25);
  CHECK(pn::sees_point(scene, {0.5, 10.0, 0.5}, light));
  // The underside: the segment's start, offset toward the light, is inside the table.
  CHECK_FALSE(pn::sees_point(scene, {0.5, 9.0, 0.5}, light));
  CHECK_FALSE(pn::sees_point(scene, {0.0, 0.0, 0.0}, light));
  CHECK(pn::sees_point(scene, {8.0, 0.0, 0.0}, light));
}

TEST_CASE("segment tests over a 4x4 light grid: none seen under the table, all far from it, 3/4 at x = 2.5") {
  const pn::Scene scene = table_scene();
  const auto lights = light_grid();
  CHECK(seen_fraction(scene, {0.0, 0.0, 0.0}, lights) == 0.0);
  CHECK(seen_fraction(scene, {8.0, 0.0, 0.0}, lights) == 1.0);
  // From (2.5, 0, 0) to a sample at (xs, 20, zs), the segment is at x = (2.5 + xs) / 2 at the table's top
  // (y = 10) and at 0.55 * 2.5 + 0.45 xs at its bottom (y = 9); |z| <= 0.375 there. It meets the table
  // (x <= 1) only for xs = -0.75 (0.875): 4 of the 16 samples.
  CHECK(seen_fraction(scene, {2.5, 0.0, 0.0}, lights) == 0.75);
  // At x = 2 the columns xs = -0.75 and -0.25 are hidden: (2 + xs) / 2 <= 1 for xs <= 0.
  CHECK(seen_fraction(scene, {2.0, 0.0, 0.3}, lights) == 0.5);
  // A point light at the centre: one hard shadow, the edge at x = 2 (x = 2 / 2 = 1 at the top).
  const std::vector<glm::dvec3> centre{{0.0, 20.0, 0.0}};
  CHECK(seen_fraction(scene, {1.9, 0.0, 0.0}, centre) == 0.0);
  CHECK(seen_fraction(scene, {2.1, 0.0, 0.0}, centre) == 1.0);
}

TEST_CASE("camera ray: the screen's centre sees the ground at the origin (the camera looks at it), box 0") {
  const auto hit = pn::ray_cast_surface_point(table_scene(), 0, 0, 1);
  REQUIRE(hit.has_value());
  CHECK(hit->box == 0);
  CHECK(glm::length(hit->position) < 1e-5);  // the camera matrices are float
}
