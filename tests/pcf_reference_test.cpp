// The pcf reference on hand-worked maps: what is covered, what occludes, the bound.
#include <catch2/catch.hpp>

#include <climits>
#include <cmath>

#include "reference/pcf_reference.h"

namespace {

// 0.1  0.5   NaN
// 0.3 -Inf   0.9
// +Inf 0.2   0.4
pn::Image hand_map() {
  pn::Image m(3, 3, 1);
  const float v[9] = {0.1f, 0.5f, NAN, 0.3f, -INFINITY, 0.9f, INFINITY, 0.2f, 0.4f};
  for (int i = 0; i < 9; ++i) m.at(i % 3, i / 3) = v[i];
  return m;
}

}  // namespace

TEST_CASE("pcf reference: the whole 3x3 map at dP 0.45, bias 0.05 has 3 occluders (0.1, 0.3, 0.2) of 9 texels") {
  const auto s = pn::pcf_reference(hand_map(), {0, 0, 3, 3}, 0.45, 0.05);
  CHECK(s.texels == 9);
  CHECK(s.occluders == 3);  // 0.4 < 0.4 is false; NaN, +Inf and -Inf never occlude
  CHECK(s.depth_sum == Approx(0.6).epsilon(1e-6));
  CHECK(s.blocker_mean() == Approx(0.2).epsilon(1e-6));
  CHECK(s.occluded_fraction() == Approx(3.0 / 9.0));
}

TEST_CASE("pcf reference: a NaN receiver occludes nothing; +Inf makes every finite texel occlude") {
  const pn::Image m = hand_map();
  const auto none = pn::pcf_reference(m, {0, 0, 3, 3}, NAN, 0.0);
  CHECK(none.occluders == 0);
  CHECK(none.texels == 9);
  CHECK(none.blocker_mean() == 0.0);
  const auto all = pn::pcf_reference(m, {0, 0, 3, 3}, INFINITY, 0.0);
  CHECK(all.occluders == 6);  // 0.1 0.5 0.3 0.9 0.2 0.4
  CHECK(all.depth_sum == Approx(2.4).epsilon(1e-6));
  CHECK(std::isfinite(all.depth_sum));
}

TEST_CASE("pcf reference: windows are clipped to the map; outside and empty windows cover nothing") {
  const pn::Image m = hand_map();
  const auto corner = pn::pcf_reference(m, {-1, -1, 2, 2}, 0.45, 0.05);  // only (0, 0) = 0.1
  CHECK(corner.texels == 1);
  CHECK(corner.occluders == 1);
  const auto far = pn::pcf_reference(m, {2, 2, 5, 5}, 0.45, 0.05);  // only (2, 2) = 0.4
  CHECK(far.texels == 1);
  CHECK(far.occluders == 0);
  CHECK(pn::pcf_reference(m, {3, 0, 2, 2}, 0.45, 0.05).texels == 0);
  CHECK(pn::pcf_reference(m, {0, -2, 3, 2}, 0.45, 0.05).texels == 0);
  CHECK(pn::pcf_reference(m, {0, 0, 0, 3}, 0.45, 0.05).texels == 0);
  CHECK(pn::pcf_reference(m, {0, 0, 3, -1}, 0.45, 0.05).texels == 0);
  CHECK(pn::pcf_reference(m, {INT_MAX - 1, 0, INT_MAX, 1}, 1.0, 0.0).texels == 0);  // no overflow
  CHECK(pn::pcf_reference(m, {INT_MIN, INT_MIN, INT_MAX, INT_MAX}, 1.0, 0.0).texels == 0);
}

TEST_CASE("pcf reference: the side bound keeps the first max_side columns and rows after clipping") {
  const pn::Image m = hand_map();
  // [0, 2) x [0, 2): 0.1 0.5 / 0.3 -Inf -> 2 occluders below 0.4.
  const auto bounded = pn::pcf_reference(m, {0, 0, 3, 3}, 0.45, 0.05, 2);
  CHECK(bounded.texels == 4);
  CHECK(bounded.occluders == 2);
  CHECK(bounded.depth_sum == Approx(0.4).epsilon(1e-6));
  // Clipped first: (-5, -5) + 10 becomes [0, 3), then bounded to [0, 2), not [-5, -3).
  const auto clipped = pn::pcf_reference(m, {-5, -5, 10, 10}, 0.45, 0.05, 2);
  CHECK(clipped.texels == 4);
  CHECK(clipped.occluders == 2);
  const pn::PcfCover c = pn::pcf_cover({1, -4, 100, 100}, 300, 300, 64);
  CHECK(c.x0 == 1);
  CHECK(c.x1 == 65);
  CHECK(c.y0 == 0);
  CHECK(c.y1 == 64);
}
