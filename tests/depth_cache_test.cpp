// The depth cache's CPU side by hand: its reference, texel rectangles and
// their merging, object bounds in the map against the ray caster, motion
// tracking, texel lists, and the animated scene's motion function P(K).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

#include "bench/cache_bench.h"
#include "cache/object_motion.h"
#include "core/error.h"
#include "device/texel_list.h"
#include "reference/depth_cache_reference.h"
#include "render/frames_job.h"
#include "scene/animated_scene.h"

namespace {
const float kInf = std::numeric_limits<float>::infinity();
const float kNan = std::numeric_limits<float>::quiet_NaN();
const pn::fixtures::AnimatedSceneFixture& moving() { return pn::find_animated_scene_fixture("moving"); }
}  // namespace

TEST_CASE("depth cache reference: min of the two, NaN and ±Inf as no occluder; the shadow test strict, NaN lit") {
  CHECK(pn::depth_cache_compose_reference(3.0f, 5.0f) == 3.0f);
  CHECK(pn::depth_cache_compose_reference(5.0f, 3.0f) == 3.0f);
  CHECK(pn::depth_cache_compose_reference(kNan, 4.0f) == 4.0f);
  CHECK(pn::depth_cache_compose_reference(-kInf, 4.0f) == 4.0f);
  CHECK(pn::depth_cache_compose_reference(kNan, -kInf) == kInf);
  CHECK(pn::depth_cache_visibility_reference(3.0f, 3.0f, 0.0f) == 1.0f);  // a receiver on the occluder is lit
  CHECK(pn::depth_cache_visibility_reference(3.0f, std::nextafter(3.0f, 4.0f), 0.0f) == 0.0f);
  CHECK(pn::depth_cache_visibility_reference(3.0f, 3.5f, 0.5f) == 1.0f);
  CHECK(pn::depth_cache_visibility_reference(3.0f, kNan, 0.0f) == 1.0f);
  CHECK(pn::depth_cache_visibility_reference(kInf, kInf, 0.0f) == 1.0f);
  CHECK(pn::depth_cache_visibility_reference(3.0f, kInf, 0.0f) == 0.0f);
}

TEST_CASE("texel rectangles: bounds, intersection, and merging overlaps into at most a given count") {
  const pn::TexelRect a{0, 0, 4, 4}, b{2, 2, 6, 5}, c{10, 10, 12, 12};
  CHECK(pn::bounding(a, b) == pn::TexelRect{0, 0, 6, 5});
  CHECK(pn::intersection(a, b) == pn::TexelRect{2, 2, 4, 4});
  CHECK(pn::intersection(a, c).empty());
  CHECK(pn::bounding(pn::TexelRect{}, c) == c);
  const auto merged = pn::merged_rects({a, c, b, pn::TexelRect{5, 5, 5, 9}}, 8);
  REQUIRE(merged.size() == 2);  // the empty one dropped, a and b merged
  CHECK(merged[0] == pn::TexelRect{0, 0, 6, 5});
  CHECK(merged[1] == c);
  // A chain: the merged rectangle meets the next one only after growing.
  const auto chain = pn::merged_rects({{0, 0, 2, 2}, {5, 0, 7, 2}, {1, 0, 6, 1}}, 8);
  REQUIRE(chain.size() == 1);
  CHECK(chain[0] == pn::TexelRect{0, 0, 7, 2});
  const auto capped = pn::merged_rects({a, c, {20, 20, 21, 21}}, 2);
  REQUIRE(capped.size() == 1);
  CHECK(capped[0] == pn::TexelRect{0, 0, 21, 21});
}

TEST_CASE("texel lists: every texel of the clipped rectangles once per rectangle, in order; too many: the whole grid") {
  pn::TexelList list;
  const pn::TexelRun run = list.add({{-1, -1, 2, 1}, {3, 3, 4, 5}}, 4, 4);  // clipped to 2×1, then 1×1
  CHECK(run.first == 0);
  CHECK(run.count == 3);
  CHECK_FALSE(run.whole);
  const pn::TexelRun second = list.add({{0, 0, 2, 2}}, 8, 8);
  CHECK(second.first == 3);
  CHECK(second.count == 4);
  const pn::TexelRun huge = list.add({{0, 0, 8192, 8192}}, 8192, 8192);
  CHECK(huge.whole);
}

TEST_CASE("map bounds: every texel whose centre ray meets a box lies inside the box's rectangle; none outside the map") {
  pn::AnimatedScene animation(moving(), 1.0, 128, "");
  for (int f : {0, 7, 40}) {
    const pn::Scene scene = animation.frame(f);
    const std::vector<glm::vec3> vertices = scene.triangles();
    const glm::mat4 light = scene.light_projection() * scene.light_view();
    const int n = scene.light.map_size;
    for (size_t b = 1; b < scene.boxes.size(); b += 7) {
      const pn::SceneObject& o = scene.objects[b];
      const pn::TexelRect r = pn::map_bounds(scene, light, vertices.data() + o.first_vertex, o.vertex_count);
      CHECK(pn::intersection(r, pn::TexelRect::square(n)) == r);
      pn::Scene alone = scene;  // the ground and this box only: where the caster sees it
      alone.boxes = {scene.boxes[0], scene.boxes[b]};
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          const float depth = pn::ray_cast_light_depth(alone, x, y);
          pn::Scene ground = alone;
          ground.boxes.resize(1);
          if (depth < pn::ray_cast_light_depth(ground, x, y)) {
            INFO("frame " << f << " box " << b << " texel " << x << ", " << y);
            CHECK((x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1));
          }
        }
    }
  }
}

TEST_CASE("motion tracking: an object is dynamic in a frame when its transform changed since the previous one") {
  pn::AnimatedScene animation(moving(), 0.3, 64, "");
  pn::ObjectMotion motion;
  pn::Scene s0 = animation.frame(0);
  CHECK_FALSE(motion.track(s0, s0.triangles()));  // no previous frame
  for (const auto& o : motion.objects()) CHECK_FALSE(o.dynamic);
  pn::Scene s1 = animation.frame(1);
  REQUIRE(motion.track(s1, s1.triangles()));
  int dynamic = 0;
  for (size_t i = 0; i < s1.objects.size(); ++i) {
    const bool moved = s1.objects[i].transform != s0.objects[i].transform;
    CHECK(motion.objects()[i].dynamic == moved);
    CHECK_FALSE(motion.objects()[i].was_dynamic);
    dynamic += moved;
  }
  CHECK(dynamic > 0);
  CHECK_FALSE(motion.objects()[0].dynamic);  // the ground never moves
  // The same frame again: nothing moved, and what moved before was dynamic.
  REQUIRE(motion.track(s1, s1.triangles()));
  for (const auto& o : motion.objects()) CHECK_FALSE(o.dynamic);
  // A scene of another layout starts over.
  pn::Scene other = s1;
  other.objects.pop_back();
  CHECK_FALSE(motion.track(other, other.triangles()));
}

TEST_CASE("animated scene: deterministic in any frame order, P's share nearest K, objects start, stop and leave the map") {
  pn::AnimatedScene a(moving(), 0.25, 64, ""), b(moving(), 0.25, 64, "");
  const pn::Scene late = a.frame(57);
  b.frame(90);
  const pn::Scene again = b.frame(57);  // stepped back from 90
  REQUIRE(late.boxes.size() == again.boxes.size());
  for (size_t i = 0; i < late.boxes.size(); ++i) {
    CHECK(late.boxes[i].lo == again.boxes[i].lo);
    CHECK(late.objects[i].transform == again.objects[i].transform);
  }
  // Boxes only: 60 movable boxes of 12 triangles; K = 0.25 is 15 boxes exactly.
  CHECK(a.movable_triangles() == 60 * 12);
  CHECK(a.moving_triangles(0) == 0);
  for (int f : {1, 21, 41}) CHECK(a.moving_triangles(f) == 15 * 12);
  pn::AnimatedScene none(moving(), 0.0, 64, ""), all(moving(), 1.0, 64, "");
  CHECK(none.moving_triangles(5) == 0);
  CHECK(all.moving_triangles(5) == all.movable_triangles());
  // Box transforms are the boxes' translations; the ground stays.
  const pn::Scene home = a.frame(0);
  for (size_t i = 1; i < late.boxes.size(); ++i) {
    const glm::vec3 t(late.objects[i].transform[3]);
    CHECK(late.boxes[i].lo == home.boxes[i].lo + t);
  }
  CHECK(late.boxes[0].lo == home.boxes[0].lo);
  // Over 100 frames at K = 1 some box leaves the light's frustum (±11.5 at the ground) and comes back.
  pn::AnimatedScene many(moving(), 1.0, 64, "");
  std::set<size_t> left;
  for (int f = 0; f < 100; ++f) {
    const pn::Scene s = many.frame(f);
    for (size_t i = 1; i < s.boxes.size(); ++i)
      if (s.boxes[i].lo.x > 12.0f || s.boxes[i].hi.x < -12.0f || s.boxes[i].lo.z > 12.0f || s.boxes[i].hi.z < -12.0f) left.insert(i);
  }
  CHECK(left.size() >= 3);
  CHECK_THROWS_WITH(pn::AnimatedScene(moving(), 1.5, 64, ""), Catch::Contains("expected 0 <= K <= 1"));
  CHECK_THROWS_WITH(pn::find_animated_scene_fixture("city"), Catch::Contains("expected one of moving, moving_city"));
}

TEST_CASE("animated scene with the test model: the model is one object, turning as it moves") {
  const std::filesystem::path model = pn::fixtures::kAnimatedModel;
  if (!std::filesystem::exists(model)) {
    WARN("no " << model.string() << ": the model case is not exercised");
    return;
  }
  pn::AnimatedScene a(moving(), 1.0, 64, model);
  const pn::Scene s0 = a.frame(0), s3 = a.frame(3);
  REQUIRE(s0.objects.size() == 1 + 60 + 1);
  CHECK(s0.objects.back().vertex_count == static_cast<int>(s0.mesh.size()));
  CHECK(s0.objects.back().first_vertex == 36 * 61);
  CHECK(s0.objects.back().transform != s3.objects.back().transform);
  CHECK(a.movable_triangles() == 60 * 12 + static_cast<int>(s0.mesh.size() / 3));
}

TEST_CASE("bench cache and render --frames: bad settings are refused by name before any GL") {
  pn::CacheBenchSetup bench;
  CHECK_NOTHROW(pn::validate_cache_bench_setup(bench));
  bench.ks = {0.5, -0.1};
  CHECK_THROWS_WITH(pn::validate_cache_bench_setup(bench), Catch::Contains("K -0.1"));
  bench = {};
  bench.sources = {"full", "lru"};
  CHECK_THROWS_WITH(pn::validate_cache_bench_setup(bench), Catch::Contains("unknown shadow-map source 'lru'"));
  bench = {};
  bench.frames = 0;
  CHECK_THROWS_WITH(pn::validate_cache_bench_setup(bench), Catch::Contains("frames 0: expected 1..1000"));
  pn::FramesSetup frames;
  CHECK_NOTHROW(pn::validate_frames_setup(frames));
  frames.scene = "boxes";
  CHECK_THROWS_WITH(pn::validate_frames_setup(frames), Catch::Contains("animated scene 'boxes'"));
  frames = {};
  frames.frames = 1001;
  CHECK_THROWS_WITH(pn::validate_frames_setup(frames), Catch::Contains("frames 1001: expected 1..1000"));
}
