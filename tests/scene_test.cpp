// Scene geometry and the ray-cast definition of the shadow map, by hand.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/error.h"
#include "scene/scene.h"

namespace {
const pn::fixtures::SceneFixture& scene_named(const std::string& name) {
  for (const auto& s : pn::fixtures::kScenes)
    if (name == s.name) return s;
  FAIL("no scene " << name);
  return pn::fixtures::kScenes[0];
}
}  // namespace

TEST_CASE("scenes: the ground plus their occluders, 36 vertices a box, the light validated") {
  const pn::Scene boxes = pn::make_scene(scene_named("boxes"), 64);
  CHECK(boxes.boxes.size() == 1 + 24);
  CHECK(boxes.triangles().size() == 36 * boxes.boxes.size());
  for (size_t i = 1; i < boxes.boxes.size(); ++i) {
    CHECK(boxes.boxes[i].lo.y == 0.0f);  // standing on the ground
    CHECK(boxes.boxes[i].hi.y > 0.0f);
  }
  CHECK(pn::make_scene(scene_named("fence"), 64).boxes.size() == 1 + 16 + 2);
  CHECK_THROWS_WITH(pn::make_scene(scene_named("boxes"), 1), Catch::Contains("shadow map size 1"));
}

TEST_CASE("ray cast: the texels at the map's centre see the tall blocker's top at depth 20 - 10 = 10") {
  const pn::Scene tall = pn::make_scene(scene_named("tall_blocker"), 64);
  // Texel centres (31.5, 31.5) and (32.5, 32.5) are 0.5 texel from the axis: still on the 2x2 top.
  CHECK(pn::ray_cast_light_depth(tall, 31, 31) == Approx(10.0).epsilon(1e-6));
  CHECK(pn::ray_cast_light_depth(tall, 32, 32) == Approx(10.0).epsilon(1e-6));
  // A corner texel sees the ground (depth 20) or beyond it nothing: the ground spans +-10 at depth 20,
  // the view +-20 tan(30 deg) = +-11.5.
  CHECK(std::isinf(pn::ray_cast_light_depth(tall, 0, 0)));
  CHECK(pn::ray_cast_light_depth(tall, 8, 32) == Approx(20.0).epsilon(1e-6));
}

TEST_CASE("G-buffer definition: a pixel's ray-cast receiver lies on a surface it sees; a shifted one does not") {
  const pn::Scene boxes = pn::make_scene(scene_named("boxes"), 256);
  int checked = 0;
  for (int y = 10; y < 256; y += 37)
    for (int x = 10; x < 256; x += 41) {
      const pn::Receiver r = pn::ray_cast_receiver(boxes, x, y, 256);
      if (!r.valid) continue;
      ++checked;
      INFO("pixel " << x << ", " << y << ": u " << r.u << " v " << r.v << " depth " << r.depth);
      CHECK(pn::receiver_on_surface_near_pixel(boxes, r.u, r.v, r.depth, x, y, 256, 1e-6));
      CHECK_FALSE(pn::receiver_on_surface_near_pixel(boxes, r.u + 8.0, r.v, r.depth, x, y, 256, 1e-3));
    }
  CHECK(checked > 20);
}
