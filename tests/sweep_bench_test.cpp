// bench sweep's logic without GL: the scaled light, the time growth across a
// sweep, the exact-PCSS filter, and bad setups refused naming the setting.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "bench/sweep_bench.h"
#include "core/error.h"

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();
}  // namespace

TEST_CASE("sweep scene: the tall blocker's light width 4 times 8 is 32, the rest of the scene unchanged") {
  const auto& fixture = pn::find_scene_fixture("tall_blocker");
  const pn::Scene one = pn::make_scene(fixture, 64);
  const pn::Scene wide = pn::sweep_scene(fixture, 64, 8.0);
  CHECK(one.light.width == 4.0);
  CHECK(wide.light.width == 32.0);
  CHECK(wide.light.map_size == 64);
  CHECK(wide.light.near_plane == one.light.near_plane);
  CHECK(wide.light.far_plane == one.light.far_plane);
  CHECK(wide.boxes.size() == one.boxes.size());
  // The penumbra grows with the width: Eq. (1) is linear in w_L.
  CHECK(wide.light.penumbra_texels(20.0, 10.0) == Approx(8.0 * one.light.penumbra_texels(20.0, 10.0)));
}

TEST_CASE("sweep scene: factors that are not finite and > 0 are refused (negative)") {
  const auto& fixture = pn::find_scene_fixture("boxes");
  CHECK_THROWS_WITH(pn::sweep_scene(fixture, 64, 0.0), "light width factor 0: expected a finite number > 0");
  CHECK_THROWS_WITH(pn::sweep_scene(fixture, 64, -2.0), "light width factor -2: expected a finite number > 0");
  CHECK_THROWS_WITH(pn::sweep_scene(fixture, 64, kNaN), "light width factor nan: expected a finite number > 0");
  CHECK_THROWS_WITH(pn::sweep_scene(fixture, 64, kInf), "light width factor inf: expected a finite number > 0");
  // Finite factors, but a light wider than the ray-traced truth represents (issue 26 B1).
  CHECK_THROWS_WITH(pn::sweep_scene(fixture, 64, 1e308),
                    Catch::StartsWith("light width factor 1e+308: the light would be inf wide, past the 1e+15"));
  CHECK_THROWS_WITH(pn::sweep_scene(fixture, 64, 1e19), Catch::Contains("expected a factor <= 3.33333e+14"));
  CHECK_NOTHROW(pn::sweep_scene(fixture, 64, 3e14));
}

TEST_CASE("time growth: last counted time over first, from the first factor with a time to the last") {
  const auto g = pn::time_growth({{1, 100.0}, {2, 110.0}, {4, 120.0}, {8, 150.0}});
  REQUIRE(g);
  CHECK(g->from == 1);
  CHECK(g->to == 8);
  CHECK(g->ratio == Approx(1.5));
  // Exact PCSS stopping at x2: its growth is x1 -> x2.
  const auto exact = pn::time_growth({{1, 2000.0}, {2, 8000.0}});
  REQUIRE(exact);
  CHECK(exact->to == 2);
  CHECK(exact->ratio == Approx(4.0));
  // Times that are not finite and > 0 do not count.
  const auto gaps = pn::time_growth({{1, 0.0}, {2, 50.0}, {4, kNaN}, {8, 75.0}});
  REQUIRE(gaps);
  CHECK(gaps->from == 2);
  CHECK(gaps->to == 8);
  CHECK(gaps->ratio == Approx(1.5));
  CHECK_FALSE(pn::time_growth({}));
  CHECK_FALSE(pn::time_growth({{1, 10.0}}));
  CHECK_FALSE(pn::time_growth({{1, 10.0}, {2, -1.0}}));
}

TEST_CASE("exact technique: exact PCSS with or without overrides, nothing else") {
  CHECK(pn::is_exact_technique("exact"));
  CHECK(pn::is_exact_technique("exact:bias=0.01"));
  CHECK_FALSE(pn::is_exact_technique("exactly"));
  CHECK_FALSE(pn::is_exact_technique("fast"));
  CHECK_FALSE(pn::is_exact_technique("fast-all-off"));
}

TEST_CASE("sweep setup: the defaults validate; bad settings are refused naming the setting (negative)") {
  pn::SweepBenchSetup s;
  CHECK_NOTHROW(pn::validate_sweep_setup(s));
  CHECK(s.scenes == std::vector<std::string>{"tall_blocker", "boxes"});
  CHECK(s.factors == std::vector<double>{1, 2, 4, 8});
  CHECK(s.sizes == std::vector<int>{512});
  CHECK(s.exact_up_to == 2.0);
  s.exact_up_to = kInf;  // exact PCSS at every factor
  CHECK_NOTHROW(pn::validate_sweep_setup(s));
  const auto refused = [](auto change, const std::string& message) {
    pn::SweepBenchSetup bad;
    change(bad);
    CHECK_THROWS_WITH(pn::validate_sweep_setup(bad), message);
  };
  refused([](auto& b) { b.scenes = {"tall_blocker", "nope"}; },
          "unknown scene 'nope': expected one of boxes, fence, tall_blocker");
  refused([](auto& b) { b.factors = {1, 0}; }, "light width factor 0: expected a finite number > 0");
  refused([](auto& b) { b.factors = {kNaN}; }, "light width factor nan: expected a finite number > 0");
  refused([](auto& b) { b.sizes = {512, 8}; }, "size 8: expected 16..4096");
  refused([](auto& b) { b.sizes = {8192}; }, "size 8192: expected 16..4096");
  refused([](auto& b) { b.repeats = 0; }, "repeats 0: expected 1..100");
  refused([](auto& b) { b.truth_samples = 65; }, "truth samples 65: expected 1..64 per side");
  refused([](auto& b) { b.exact_up_to = 0; }, "exact up to 0: expected a light width factor > 0");
  refused([](auto& b) { b.exact_up_to = kNaN; }, "exact up to nan: expected a light width factor > 0");
  refused([](auto& b) { b.factors.clear(); }, "sweep light width factors: 0 entries: expected 1..32");
  refused([](auto& b) { b.scenes.clear(); }, "sweep scenes: 0 entries: expected 1..32");
  refused([](auto& b) { b.sizes.assign(33, 512); }, "sweep sizes: 33 entries: expected 1..32");
}
