// The physical reference's CPU definition, by hand on a table top floating
// under the light (hand_scene.h): its sample points, segment tests, the
// fraction at points under, beside and far from the table, and the
// shadow-map answers that bound what a raster may give.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "hand_scene.h"
#include "scene/light_samples.h"
#include "scene/visibility_reference.h"

using pn::test::table_scene;

TEST_CASE("light samples: 4x4 cell centres of a width-2 light at offsets -0.75, -0.25, 0.25, 0.75 in its x/z plane") {
  const auto points = pn::light_sample_points(table_scene(), 4);
  REQUIRE(points.size() == 16);
  const double offsets[4] = {-0.75, -0.25, 0.25, 0.75};
  std::vector<std::pair<double, double>> seen;
  for (const auto& p : points) {
    CHECK(p.y == Approx(20.0).margin(1e-6));
    seen.push_back({p.x, p.z});
  }
  for (double x : offsets)
    for (double z : offsets)
      CHECK(std::count_if(seen.begin(), seen.end(), [&](const auto& s) {
              return std::fabs(s.first - x) < 1e-6 && std::fabs(s.second - z) < 1e-6;
            }) == 1);
}

TEST_CASE("light samples: a light of width 0 gives its centre, one sample per side gives the centre too") {
  for (const auto& p : pn::light_sample_points(table_scene(64, 0.0), 3))
    CHECK(glm::length(p - glm::vec3(0, 20, 0)) < 1e-6f);
  const auto one = pn::light_sample_points(table_scene(), 1);
  REQUIRE(one.size() == 1);
  CHECK(glm::length(one[0] - glm::vec3(0, 20, 0)) < 1e-6f);
}

TEST_CASE("negative: light samples per side 0 and 65 are refused naming the range") {
  CHECK_THROWS_WITH(pn::light_sample_points(table_scene(), 0),
                    Catch::Contains("light samples per side 0: expected 1 to 64"));
  CHECK_THROWS_AS(pn::light_sample_points(table_scene(), 65), pn::Error);
}

TEST_CASE("segment tests: the table's top sees the light, its underside and the ground under it do not") {
  const pn::Scene scene = table_scene();
  const glm::dvec3 light(0.25, 20.0, -0.25);
  CHECK(pn::sees_point(scene, {0.5, 10.0, 0.5}, light));
  // The underside: the segment's start, offset toward the light, is inside the table.
  CHECK_FALSE(pn::sees_point(scene, {0.5, 9.0, 0.5}, light));
  CHECK_FALSE(pn::sees_point(scene, {0.0, 0.0, 0.0}, light));
  CHECK(pn::sees_point(scene, {8.0, 0.0, 0.0}, light));
}

TEST_CASE("visible fraction: 0 under the table, 1 far from it, 3/4 at x = 2.5 (only the column xs = -0.75 hidden)") {
  const pn::Scene scene = table_scene();
  const auto lights = pn::light_sample_points(scene, 4);
  CHECK(pn::visible_fraction(scene, {0.0, 0.0, 0.0}, lights) == 0.0);
  CHECK(pn::visible_fraction(scene, {8.0, 0.0, 0.0}, lights) == 1.0);
  // From (2.5, 0, 0) to a sample at (xs, 20, zs), the segment is at x = (2.5 + xs) / 2 at the table's top
  // (y = 10) and at 0.55 * 2.5 + 0.45 xs at its bottom (y = 9); |z| <= 0.375 there. It meets the table
  // (x <= 1) only for xs = -0.75 (0.875): 4 of the 16 samples.
  CHECK(pn::visible_fraction(scene, {2.5, 0.0, 0.0}, lights) == 0.75);
  // At x = 2 the columns xs = -0.75 and -0.25 are hidden: (2 + xs) / 2 <= 1 for xs <= 0.
  CHECK(pn::visible_fraction(scene, {2.0, 0.0, 0.3}, lights) == 0.5);
  // A light of width 0: one hard shadow, the edge at x = 2 for the centre (x = 2 / 2 = 1 at the top).
  const pn::Scene point_light = table_scene(64, 0.0);
  const auto centre = pn::light_sample_points(point_light, 2);
  CHECK(pn::visible_fraction(point_light, {1.9, 0.0, 0.0}, centre) == 0.0);
  CHECK(pn::visible_fraction(point_light, {2.1, 0.0, 0.0}, centre) == 1.0);
}

TEST_CASE("camera ray: the screen's centre sees the ground at the origin (the camera looks at it), box 0") {
  const auto hit = pn::ray_cast_surface_point(table_scene(), 0, 0, 1);
  REQUIRE(hit.has_value());
  CHECK(hit->box == 0);
  CHECK(glm::length(hit->position) < 1e-5);  // the camera matrices are float
}

TEST_CASE("shadow-map answers: lit far from the table, shadowed under it and just past the edge in the edge's texel") {
  const pn::Scene scene = table_scene(64);  // the centre's map: the table's top at depth 10
  const pn::ShadowMapAnswers far = pn::shadow_map_answers(scene, {8.0, 0.0, 0.0}, 0.02);
  CHECK((far.lit && !far.shadowed));
  const pn::ShadowMapAnswers under = pn::shadow_map_answers(scene, {0.0, 0.0, 0.0}, 0.02);
  CHECK((!under.lit && under.shadowed));
  // At the ground 64 texels span 2 * 20 tan 30 = 23.094 units, 0.36084 a texel, texel 32 starting at x = 0.
  // The centre's hard edge is at x = 2 (the table's edge, x = 1 at depth 10, scaled by 20 / 10). The receiver
  // x = 2.1 lies in texel floor(32 + 2.1 / 0.36084) = 37, whose centre ray (x = 5.5 * 0.36084 = 1.985 at the
  // ground) meets the table: the map shadows it, the segment (x = 1.05 at the table's top) lights it.
  CHECK(pn::sees_point(scene, {2.1, 0.0, 0.0}, {0.0, 20.0, 0.0}));
  const pn::ShadowMapAnswers edge = pn::shadow_map_answers(scene, {2.1, 0.0, 0.0}, 0.02);
  CHECK((!edge.lit && edge.shadowed));
  // Texel 38 (x from 2.165) sees the ground: lit, like the segment.
  const pn::ShadowMapAnswers past = pn::shadow_map_answers(scene, {2.2, 0.0, 0.0}, 0.02);
  CHECK((past.lit && !past.shadowed));
}

TEST_CASE("visibility reference: the exact fraction lies within the raster's range at every pixel; sky is 1") {
  const pn::Scene scene = table_scene(64);
  const pn::VisibilityReference ref = pn::visibility_reference(scene, 24, 3, 0.02);
  int sky = 0, shaded = 0;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x) {
      CHECK(ref.lowest.at(x, y) <= ref.fraction.at(x, y));
      CHECK(ref.fraction.at(x, y) <= ref.highest.at(x, y));
      if (ref.box.at(x, y) < 0) {
        ++sky;
        CHECK(ref.fraction.at(x, y) == 1.0f);
      }
      if (ref.fraction.at(x, y) < 1.0f) ++shaded;
    }
  CHECK(sky > 0);
  CHECK(shaded > 0);
}
