// The city (fixtures/city_scenes.h) as its docs describe it, its sun's whole-scene map, and
// the camera path; the sun's light validated.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/error.h"
#include "scene/city_scene.h"

namespace {
const pn::Scene& city() {
  static const pn::Scene scene = pn::make_city_scene(pn::fixtures::kCityScenes[0], 2048);
  return scene;
}
}  // namespace

TEST_CASE("city: 400 x 400 ground, 536 seeded buildings off the camera's street, 66 poles, six models") {
  const pn::Scene& s = city();
  REQUIRE(s.boxes.size() == 603);
  CHECK(s.boxes[0].lo == glm::vec3(-200, -1, -200));
  CHECK(s.boxes[0].hi == glm::vec3(200, 0, 200));
  int poles = 0;
  for (size_t b = 1; b < s.boxes.size(); ++b) {
    const pn::Box& box = s.boxes[b];
    INFO("box " << b);
    CHECK(box.lo.y == 0.0f);
    CHECK(box.lo.x >= -200.0f);
    CHECK(box.hi.x <= 200.0f);
    CHECK(box.hi.y <= pn::fixtures::kCityMaxHeight);
    const bool pole = box.hi.x - box.lo.x < 0.3f;
    poles += pole;
    if (!pole) CHECK((box.lo.x >= 4.0f || box.hi.x <= -4.0f));  // the street x in [-4, 4] is clear of buildings
  }
  CHECK(poles == 66);
  CHECK(s.mesh.size() == 3u * (3 * 1368 + 3 * 3732));  // spider and Wuson, three of each
  CHECK(s.triangles().size() == 3u * 22536);
}

TEST_CASE("city: the sun at 35 degrees, 0.53 degrees wide, one orthographic map over the scene's bounds") {
  const pn::Scene& s = city();
  REQUIRE(s.sun);
  const glm::vec3 d = glm::normalize(s.sun->direction);
  CHECK(std::asin(-d.y) * 180.0 / 3.14159265358979 == Approx(35.0).margin(1e-4));
  CHECK(s.light.spread == Approx(2 * std::tan(0.5 * 0.53 * 3.14159265358979 / 180)).epsilon(1e-6));
  CHECK(s.light.orthographic());
  CHECK(s.light.width == 0.0);
  // Every corner of the bounds inside the map and its depth range.
  const auto [lo, hi] = s.bounds();
  const glm::dmat4 vp = glm::dmat4(s.light_projection()) * glm::dmat4(s.light_view());
  for (int c = 0; c < 8; ++c) {
    const glm::dvec4 p = vp * glm::dvec4((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z, 1.0);
    CHECK(std::fabs(p.x) <= 1.0 + 1e-6);
    CHECK(std::fabs(p.y) <= 1.0 + 1e-6);
    CHECK(std::fabs(p.z) <= 1.0 + 1e-6);
  }
  // The whole-scene map's texel (docs: 27 cm at 2048²).
  CHECK(s.light.texel_world == Approx(0.267).margin(0.001));
}

TEST_CASE("city: the camera path steps 0.05 units and turns 0.05 degrees a frame; a bad sun is refused") {
  const pn::SceneCamera a = pn::city_camera(0), b = pn::city_camera(10);
  CHECK(a.eye.y == pn::fixtures::kCityCameraHeight);
  CHECK(glm::length(b.eye - a.eye) == Approx(0.5).epsilon(1e-5));
  const glm::vec3 fa = glm::normalize(a.target - a.eye), fb = glm::normalize(b.target - b.eye);
  CHECK(std::acos(std::min(1.0f, glm::dot(fa, fb))) * 180.0 / 3.14159265358979 == Approx(0.5 * std::cos(0.1047)).epsilon(0.02));
  CHECK(a.near_plane == 0.5f);
  CHECK(a.far_plane == 400.0f);
  pn::Scene s = city();
  CHECK_THROWS_WITH(pn::light_by_sun(s, {0, -1, 0}, 0.0), "sun angular diameter 0 degrees: expected 0 < diameter < 10");
  CHECK_THROWS_WITH(pn::light_by_sun(s, {0, 0, 0}, 0.01), Catch::Contains("light direction (0, 0, 0)"));
  CHECK(pn::find_city_scene_fixture_or_null("village") == nullptr);
}

TEST_CASE("city: a scene resized to another map size is the scene made at that size") {
  const pn::Scene resized = pn::with_shadow_map_size(city(), 512);
  const pn::Scene made = pn::make_city_scene(pn::fixtures::kCityScenes[0], 512);
  CHECK(resized.light.map_size == 512);
  CHECK(resized.light.texel_world == made.light.texel_world);
  CHECK(resized.light.near_plane == made.light.near_plane);
  CHECK(resized.light.far_plane == made.light.far_plane);
  CHECK(resized.light_projection() == made.light_projection());
  CHECK(resized.triangles() == made.triangles());
  CHECK_THROWS_WITH(pn::with_shadow_map_size(city(), 1), Catch::Contains("shadow map size 1: expected N >= 2"));
}
