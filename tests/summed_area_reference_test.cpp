// The summed_area reference on hand-worked maps: the fixed-point values, what
// is covered, what is excluded, the wrap, the bounds.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include "reference/summed_area_reference.h"

namespace {

//  1.5   NaN   -2.25
//  4    +Inf    0.5
// -Inf  10      3
pn::Image hand_map() {
  pn::Image m(3, 3, 1);
  const float v[9] = {1.5f, NAN, -2.25f, 4.0f, INFINITY, 0.5f, -INFINITY, 10.0f, 3.0f};
  for (int i = 0; i < 9; ++i) m.at(i % 3, i / 3) = v[i];
  return m;
}

constexpr std::int64_t kOne = std::int64_t{1} << 20;  // 1.0 at the default 20 fraction bits

}  // namespace

TEST_CASE("summed_area reference: q(d) rounds d * 2^F half to even and clamps at 2^(52-F)") {
  CHECK(pn::kSummedAreaFractionBits == 20);
  CHECK(pn::summed_area_fixed(1.0) == kOne);
  CHECK(pn::summed_area_fixed(-2.25) == -9 * kOne / 4);
  CHECK(pn::summed_area_fixed(std::ldexp(1.0, -21)) == 0);      // half a step: to even, 0
  CHECK(pn::summed_area_fixed(3 * std::ldexp(1.0, -21)) == 2);  // 1.5 steps: 2
  CHECK(pn::summed_area_fixed(-3 * std::ldexp(1.0, -21)) == -2);
  CHECK(pn::summed_area_fixed(1e-7) == 0);  // 0.105 steps
  CHECK(pn::summed_area_fixed(1e10) == std::int64_t{1} << 52);
  CHECK(pn::summed_area_fixed(-1e10) == -(std::int64_t{1} << 52));
  CHECK(pn::summed_area_fixed(2.5, 0) == 2);
  CHECK(pn::summed_area_fixed(3.5, 0) == 4);
  CHECK(pn::summed_area_fixed(1000.0, 40) == std::int64_t{1000} << 40);
  CHECK_THROWS(pn::summed_area_fixed(1.0, 53));
  CHECK_THROWS(pn::summed_area_fixed(1.0, -1));
}

TEST_CASE("summed_area reference: a 64-bit fixed-point sum reads as signed two's complement times 2^-F") {
  CHECK(pn::summed_area_fixed_value(static_cast<std::uint64_t>(3 * kOne)) == 3.0);
  CHECK(pn::summed_area_fixed_value(~std::uint64_t{0}) == -std::ldexp(1.0, -20));  // -1 step
  CHECK(pn::summed_area_fixed_value(std::uint64_t{1} << 63) == -std::ldexp(1.0, 43));
  CHECK(pn::summed_area_fixed_value(std::uint64_t{5} << 40, 40) == 5.0);
}

TEST_CASE("summed_area reference: the whole 3x3 map sums its 6 finite depths to 16.75; NaN and ±Inf are covered, not counted") {
  const auto s = pn::summed_area_reference(hand_map(), {0, 0, 3, 3});
  CHECK(s.texels == 9);
  CHECK(s.count == 6);
  CHECK(s.sum == 16.75);  // 1.5 - 2.25 + 4 + 0.5 + 10 + 3
  CHECK(s.magnitude == 21.25);
  CHECK(s.fixed_sum == static_cast<std::uint64_t>(67 * kOne / 4));
  CHECK(s.fixed_sum_fits());
  CHECK(s.mean() == Approx(16.75 / 6.0));
  // Every finite depth here is a multiple of 2^-20, but 1.5, 2.25, 4, 0.5 and 3 are below 2^(23-20) = 8:
  // the bound allows 2^-21 for each of them; 10 is exact by its float format.
  CHECK(s.quantisation_bound == 5 * std::ldexp(1.0, -21));
}

TEST_CASE("summed_area reference: rectangles are clipped to the map; outside, empty and negative ones cover nothing") {
  const pn::Image m = hand_map();
  const auto corner = pn::summed_area_reference(m, {-1, -1, 2, 2});  // only (0, 0) = 1.5
  CHECK(corner.texels == 1);
  CHECK(corner.count == 1);
  CHECK(corner.sum == 1.5);
  const auto right = pn::summed_area_reference(m, {2, -5, 9, 9});  // column 2 rows 0..3: -2.25, 0.5, 3
  CHECK(right.texels == 3);
  CHECK(right.sum == 1.25);
  CHECK(right.fixed_sum == static_cast<std::uint64_t>(5 * kOne / 4));
  const auto negative_only = pn::summed_area_reference(m, {2, 0, 1, 1});  // -2.25: two's complement
  CHECK(negative_only.fixed_sum == static_cast<std::uint64_t>(-9 * kOne / 4));
  const auto middle = pn::summed_area_reference(m, {1, 0, 1, 3});  // NaN, +Inf, 10
  CHECK(middle.texels == 3);
  CHECK(middle.count == 1);
  CHECK(middle.sum == 10.0);
  for (const pn::SummedAreaRect r : {pn::SummedAreaRect{3, 0, 2, 2}, {0, -2, 3, 2}, {0, 0, 0, 3}, {0, 0, 3, -1},
                                     {3, 3, -3, -3}, {-(1 << 30), -(1 << 30), 1 << 30, 1 << 30}}) {
    const auto s = pn::summed_area_reference(m, r);
    CHECK(s.texels == 0);
    CHECK(s.count == 0);
    CHECK(s.fixed_sum == 0);
    CHECK(s.mean() == 0.0);
  }
  CHECK(pn::summed_area_reference(m, {-1000, -1000, 1 << 20, 1 << 20}).texels == 9);
}

TEST_CASE("summed_area reference: sums wrap modulo 2^64, and say when the 64-bit sum is no longer the true one") {
  // At F = 52 a depth of 1 is the clamp 2^52: 4096 of them make 2^64 = 0 modulo 2^64.
  const pn::Image ones(64, 64, 1, 1.0f);
  const pn::SummedAreaReference reference(ones, 52);
  const auto all = reference.sums({0, 0, 64, 64});
  CHECK(all.fixed_sum == 0);
  CHECK_FALSE(all.fixed_sum_fits());
  const auto some = reference.sums({0, 0, 8, 8});  // 2^58: fits
  CHECK(some.fixed_sum == std::uint64_t{1} << 58);
  CHECK(some.fixed_sum_fits());
  // A clamped depth's quantisation bound is what the clamp removed.
  const pn::Image big(1, 1, 1, 3.0f);
  CHECK(pn::summed_area_reference(big, {0, 0, 1, 1}, 52).quantisation_bound == 2.0);
}

TEST_CASE("summed_area reference: the float bounds are 2^-21 per small depth plus 2u + u^2 of the sum, and 0 for empty") {
  const auto s = pn::summed_area_reference(hand_map(), {0, 0, 3, 3});
  const double u = std::ldexp(1.0, -24);
  const double e = 5 * std::ldexp(1.0, -21);
  CHECK(pn::summed_area_sum_bound(s) == Approx(e + 3 * u * 16.75).epsilon(1e-6));
  CHECK(pn::summed_area_mean_bound(s) > pn::summed_area_sum_bound(s) / 6.0);
  const auto empty = pn::summed_area_reference(hand_map(), {0, 0, 0, 0});
  CHECK(pn::summed_area_sum_bound(empty) == 0.0);
  CHECK(pn::summed_area_mean_bound(empty) == 0.0);
}

TEST_CASE("summed_area motivation: a float prefix-sum table of depths near 1000 at 1024^2 misses single texels by > 1") {
  // What the module avoids (computed here only to show the problem; the reference never builds a table).
  const int n = 1024;
  std::vector<float> table(static_cast<size_t>(n + 1) * (n + 1), 0.0f);
  const auto depth = [](int x, int y) { return 1000.0f + static_cast<float>((x * 37 + y * 101) % 97) / 97.0f; };
  const auto t = [&](int x, int y) -> float& { return table[static_cast<size_t>(y) * (n + 1) + x]; };
  for (int y = 1; y <= n; ++y)
    for (int x = 1; x <= n; ++x) t(x, y) = depth(x - 1, y - 1) + t(x - 1, y) + t(x, y - 1) - t(x - 1, y - 1);
  double worst = 0.0;
  for (int k = 0; k < 64; ++k) {
    const int x = n - 1 - k * 7, y = n - 1 - k * 5;
    const float box = t(x + 1, y + 1) - t(x, y + 1) - t(x + 1, y) + t(x, y);
    worst = std::max(worst, std::fabs(static_cast<double>(box) - depth(x, y)));
    // The fixed-point value of the same texel is its depth exactly (a float >= 8 is a multiple of 2^-20).
    CHECK(static_cast<double>(pn::summed_area_fixed(depth(x, y))) * std::ldexp(1.0, -20) == depth(x, y));
  }
  CHECK(worst > 1.0);
}
