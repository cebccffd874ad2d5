// The pyramid reference (row-segment scans) against the plain per-window scan,
// and the size rules of the pyramid.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "fixture_images/texture_fixture.h"
#include "pass_runners/depth_pyramid_pass.h"
#include "reference/depth_pyramid_reference.h"

TEST_CASE("every level of the pyramid reference equals a scan of each window (N 13 and 17, all fixtures)") {
  for (const auto& fixture : pn::fixtures::kTextureFixtures) {
    for (int n : {13, 17}) {
      const pn::Image map = pn::generate_fixture(fixture, n, n);
      for (int level = 0; level <= pn::floor_log2(n); ++level) {
        const pn::Image ref = pn::pyramid_level_reference(map, level);
        REQUIRE(ref.width == n - (1 << level) + 1);
        for (int v = 0; v < ref.height; ++v) {
          for (int u = 0; u < ref.width; ++u) {
            const pn::WindowStats s = pn::window_stats(map, u, v, 1 << level);
            INFO(fixture.name << " N " << n << " level " << level << " at (" << u << ", " << v << ")");
            CHECK(ref.at(u, v, 0) == s.min);
            CHECK(ref.at(u, v, 1) == s.max);
            if (std::isinf(s.mean)) CHECK(ref.at(u, v, 2) == static_cast<float>(s.mean));
            else CHECK(ref.at(u, v, 2) == Approx(s.mean).epsilon(1e-6));
          }
        }
      }
    }
  }
}

TEST_CASE("non-finite depths enter the pyramid as +Inf (no occluder), never NaN") {
  pn::Image map(2, 2, 1, 0.5f);
  map.at(1, 0) = std::numeric_limits<float>::quiet_NaN();
  map.at(0, 1) = -std::numeric_limits<float>::infinity();
  const pn::Image top = pn::pyramid_level_reference(map, 1);
  CHECK(top.at(0, 0, 0) == 0.5f);
  CHECK(std::isinf(top.at(0, 0, 1)));
  CHECK(top.at(0, 0, 1) > 0);
  CHECK(std::isinf(top.at(0, 0, 2)));
}

TEST_CASE("level count: floor(log2 N) + 1, bounded by the maximum level") {
  CHECK(pn::pyramid_level_count(2, 31) == 2);
  CHECK(pn::pyramid_level_count(3, 31) == 2);
  CHECK(pn::pyramid_level_count(1024, 31) == 11);
  CHECK(pn::pyramid_level_count(1023, 31) == 10);
  CHECK(pn::pyramid_level_count(1024, 4) == 5);
  CHECK(pn::DepthPyramid::memory_bytes(1024, 11) == 176u << 20);
  CHECK(pn::DepthPyramid::memory_bytes(2048, 12) == 768u << 20);
}

TEST_CASE("negative: non-square maps, N < 2 and negative maximum levels are refused") {
  CHECK_THROWS_WITH(pn::validate_shadow_map_size(64, 32), "shadow map 64x32: expected a square map (N x N)");
  CHECK_THROWS_WITH(pn::validate_shadow_map_size(1, 1), "shadow map 1x1: expected N >= 2");
  CHECK_THROWS_WITH(pn::validate_shadow_map_size(0, 0), "shadow map 0x0: expected N >= 2");
  CHECK_THROWS_WITH(pn::pyramid_level_count(64, -1), "pyramid maximum level -1: expected >= 0");
}
