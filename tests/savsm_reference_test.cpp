// The savsm reference on hand-worked values: a rectangle's brute-force mean and
// variance (clamped to the light's range, empty texels at the far plane), the
// Chebyshev blocker estimate in both of its forms, the mip cover's range and
// fetch count, a whole estimate under a point light, and bad settings.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "reference/savsm_reference.h"

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// 2×2: 10, 20 / +Inf, 30 (near 0, far 40: the empty texel reads as 40).
pn::Image square() {
  pn::Image m(2, 2);
  m.at(0, 0) = 10.0f, m.at(1, 0) = 20.0f, m.at(0, 1) = kInf, m.at(1, 1) = 30.0f;
  return m;
}

// 8×8 ground at 40 with a 2×2 blocker at 20 on texels [3, 5)².
pn::Image ground_and_blocker() {
  pn::Image m(8, 8, 1, 40.0f);
  for (int y = 3; y < 5; ++y)
    for (int x = 3; x < 5; ++x) m.at(x, y) = 20.0f;
  return m;
}

}  // namespace

TEST_CASE("savsm reference: 10, 20, +Inf, 30 on [0, 40] have mean 25 and variance 125") {
  const pn::SavsmMoments m = pn::savsm_rect_moments(square(), {0, 0, 2, 2}, 0.0, 40.0);
  CHECK(m.texels == 4);
  CHECK(m.mean == Approx(25.0));       // (10 + 20 + 40 + 30) / 4
  CHECK(m.variance == Approx(125.0));  // (225 + 25 + 225 + 25) / 4
  const pn::SavsmMoments clamped = pn::savsm_rect_moments(square(), {0, 0, 2, 1}, 15.0, 40.0);
  CHECK(clamped.mean == Approx(17.5));  // 10 reads as the near plane 15
  const pn::SavsmMoments outside = pn::savsm_rect_moments(square(), {5, 5, 3, 3}, 0.0, 40.0);
  CHECK(outside.texels == 0);
}

TEST_CASE("savsm reference: the Chebyshev blocker mu - v / (t - mu) equals (mu - p t) / (1 - p)") {
  // mean 25, variance 125, t = 39: p = 125 / (125 + 14^2) = 125 / 321.
  const pn::SavsmBlockerEstimate b = pn::savsm_blocker_from_moments(25.0, 125.0, 39.0, 0.0, 1.0);
  REQUIRE(b.has);
  const double p = 125.0 / 321.0;
  CHECK(b.depth == Approx(25.0 - 125.0 / 14.0));
  CHECK(b.depth == Approx((25.0 - p * 39.0) / (1.0 - p)));
  CHECK_FALSE(pn::savsm_blocker_from_moments(25.0, 125.0, 25.0, 0.0, 1.0).has);  // t <= mean: lit
  // A tiny occluded share (p >= 1 - 1e-4) is read as no blocker.
  CHECK_FALSE(pn::savsm_blocker_from_moments(25.0, 1e6, 26.0, 0.0, 1.0).has);
  // Clamped to [near, t]: a wide spread would put z before the near plane.
  CHECK(pn::savsm_blocker_from_moments(25.0, 900.0, 39.0, 0.0, 5.0).depth == Approx(5.0));
}

TEST_CASE("savsm reference: the mip nodes covering a square, their count (1 to 9) and their min and max") {
  const pn::Image map = ground_and_blocker();
  CHECK(pn::savsm_square_fetches({1, 1, 3, 3}, 8) == 1);   // the chain's smallest nodes, side 4: [0, 4)²
  CHECK(pn::savsm_square_fetches({2, 2, 1, 1}, 8) == 1);   // one texel: the side-4 node that holds it
  CHECK(pn::savsm_square_fetches({0, 0, 8, 8}, 8) == 4);   // side 8: nodes of side 4
  CHECK(pn::savsm_square_fetches({1, 1, 5, 5}, 8) == 4);   // side 5: nodes of side 4, [0, 4) and [4, 8)
  CHECK(pn::savsm_square_fetches({3, 3, 6, 6}, 16) == 9);  // texels 3..8: nodes of side 4 from 0, 4 and 8
  const pn::DepthRange r = pn::savsm_square_range(map, {1, 1, 3, 3});
  CHECK(r.min == 20.0f);  // the cover [0, 4)² holds the blocker's texel (3, 3)
  CHECK(r.max == 40.0f);
}

TEST_CASE("savsm reference: under a point light a receiver below the blocker is dark, one beside it lit") {
  pn::LightModel light;
  light.width = 0.0;  // a point light: one-texel search and filter squares
  light.near_plane = 1.0;
  light.far_plane = 60.0;
  light.fov_radians = 1.0;
  light.map_size = 8;
  const pn::Image map = ground_and_blocker();
  const pn::SavsmSettings s;  // min blocker, bound, a = 0.2
  const pn::SavsmEstimate under = pn::savsm_reference(map, light, {3.5f, 3.5f, 40.0f}, s);
  CHECK(under.surface);
  CHECK(under.has_blocker);
  CHECK(under.blocker == 20.0);
  CHECK(under.filter.width == 1);
  // The texel's side-4 node [0, 4)² holds ground at 40 too: the bound leaves it to the moments.
  CHECK(under.bound != PN_VSM_BOUND_SHADOWED);
  CHECK(under.visibility == 0.0);
  CHECK(pn::savsm_fetches(under, s, 8) == 1 + 4 + 1);  // mip node, filter moments, mip node
  // Every side-4 node holds a texel of the blocker: the bound no longer says lit beside it, the
  // moments of its one texel do.
  const pn::SavsmEstimate beside = pn::savsm_reference(map, light, {0.5f, 0.5f, 40.0f}, s);
  CHECK_FALSE(beside.lit_by_bound);
  CHECK(beside.visibility == 1.0);
  CHECK(pn::savsm_fetches(beside, s, 8) == 1 + 4 + 1);  // mip node, filter moments, mip node
  const pn::SavsmEstimate nan = pn::savsm_reference(map, light, {0.5f, 0.5f, std::nanf("")}, s);
  CHECK_FALSE(nan.surface);
  CHECK(nan.visibility == 1.0);
}

TEST_CASE("negative: savsm settings out of range are refused, naming the setting") {
  pn::SavsmSettings s;
  s.bias = -1.0f;
  CHECK_THROWS_WITH(s.validate(), Catch::Contains("savsm bias -1"));
  s = {};
  s.bleeding_reduction = 1.0f;
  CHECK_THROWS_WITH(s.validate(), Catch::Contains("bleeding reduction 1"));
  s = {};
  s.min_variance = std::nanf("");
  CHECK_THROWS_WITH(s.validate(), Catch::Contains("min variance"));
  s = {};
  s.filter_scale = kInf;
  CHECK_THROWS_WITH(s.validate(), Catch::Contains("filter scale"));
}
