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
  for (const pn::Rect r : {pn::Rect{3, 0, 2, 2}, {0, -2, 3, 2}, {0, 0, 0, 3}, {0, 0, 3, -1},
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

// ---- Moments tables ----------------------------------------------------------

namespace {

constexpr double kU = 0x1p-24;

// Depths 1, 3 / NaN, 2 in the range [0, 4] (offset 0, scale 1/4: every x exact): x = 0.25, 0.75, 1, 0.5.
pn::Image moments_hand_map() {
  pn::Image m(2, 2, 1);
  m.at(0, 0) = 1.0f, m.at(1, 0) = 3.0f, m.at(0, 1) = NAN, m.at(1, 1) = 2.0f;
  return m;
}

constexpr pn::MomentsDepthRange kQuarter{0.0, 4.0, 0.0f, 0.25f};

}  // namespace

TEST_CASE("summed_area moments reference: x is clamp((d - offset) * scale) in float, 1 for NaN and ±Inf; q rounds x 2^B half to even") {
  CHECK(pn::summed_area_unit_depth(1.0f, 0.0f, 0.25f) == 0.25f);
  CHECK(pn::summed_area_unit_depth(-3.0f, 0.0f, 0.25f) == 0.0f);  // before near: 0
  CHECK(pn::summed_area_unit_depth(9.0f, 0.0f, 0.25f) == 1.0f);   // past far: 1
  for (float d : {NAN, INFINITY, -INFINITY}) CHECK(pn::summed_area_unit_depth(d, 0.0f, 0.25f) == 1.0f);
  // Two roundings, not a division: 19 * float(1/99) in float.
  const float scale = static_cast<float>(1.0 / 99.0);
  CHECK(pn::summed_area_unit_depth(20.0f, 1.0f, scale) == 19.0f * scale);
  CHECK(pn::summed_area_true_unit_depth(20.0, 1.0, 100.0) == 19.0 / 99.0);
  CHECK(pn::summed_area_true_unit_depth(-INFINITY, 1.0, 100.0) == 1.0);  // the module's definition, not the clamp's 0
  CHECK(pn::kSummedAreaMomentBits == 18);
  CHECK(pn::summed_area_moment_q(0.25f) == 1u << 16);
  CHECK(pn::summed_area_moment_q(1.0f) == 1u << 18);
  CHECK(pn::summed_area_moment_q(0x1p-19f) == 0u);      // half a step: to even, 0
  CHECK(pn::summed_area_moment_q(3 * 0x1p-19f) == 2u);  // 1.5 steps: 2
  CHECK(pn::summed_area_moment_q(0.3f, 0) == 0u);
  CHECK(pn::summed_area_moment_q(0.5f, 0) == 0u);  // 0.5: to even
  CHECK(pn::summed_area_moment_q(1.0f, 0) == 1u);
  CHECK_THROWS(pn::summed_area_moment_q(0.5f, 19));
  CHECK_THROWS(pn::summed_area_moment_q(0.5f, -1));
}

TEST_CASE("summed_area moments reference: the 2x2 hand map's sums, mean 0.625 and variance 0.078125; NaN counts as x = 1") {
  const pn::SummedAreaMomentsReference reference(moments_hand_map(), kQuarter);
  const auto s = reference.sums({0, 0, 2, 2});
  CHECK(s.texels == 4);
  CHECK(s.sum_q == 10u << 16);                       // (1 + 3 + 4 + 2) 2^16
  CHECK(s.sum_q2 == std::uint64_t{30} << 32);        // (1 + 9 + 16 + 4) 2^32
  CHECK(s.mean == 0.625);                            // (0.25 + 0.75 + 1 + 0.5) / 4
  CHECK(s.variance == 0.078125);                     // 1.875 / 4 − 0.625²
  CHECK(s.quantised_mean == 0.625);
  CHECK(s.quantised_variance == 0.078125);
  const auto right = reference.sums({1, -1, 5, 2});  // column 1, row 0 only: x = 0.75
  CHECK(right.texels == 1);
  CHECK(right.sum_q == 3u << 16);
  CHECK(right.sum_q2 == std::uint64_t{9} << 32);
  CHECK(right.mean == 0.75);
  CHECK(right.variance == 0.0);
  for (const pn::Rect r : {pn::Rect{2, 0, 1, 1}, {0, 0, 0, 2}, {2, 2, -2, -2}}) {
    const auto e = reference.sums(r);
    CHECK(e.texels == 0);
    CHECK(e.sum_q == 0);
    CHECK(e.mean == 0.0);
    CHECK(reference.fixed_bound(e).mean == 0.0);
    CHECK(reference.float_bound(e).variance == 0.0);
  }
}

TEST_CASE("summed_area moments reference: sums of q and q^2 are taken modulo 2^64, the moments from the true sums") {
  // At B = 18 no map of up to 2^28 texels reaches 2^64; B = 0 with x = 1 gives q = 1, q^2 = 1:
  // small numbers, exact. What wraps is only the 64-bit words, so: a large constant map at B = 18.
  const pn::Image ones(300, 300, 1, INFINITY);  // x = 1: q = 2^18, q^2 = 2^36
  const pn::SummedAreaMomentsReference reference(ones, kQuarter);
  const auto s = reference.sums({0, 0, 300, 300});
  CHECK(s.sum_q == std::uint64_t{90000} << 18);
  CHECK(s.sum_q2 == std::uint64_t{90000} << 36);  // 2^52.5: still below 2^64
  CHECK(s.mean == 1.0);
  CHECK(s.variance == 0.0);
  CHECK(s.quantised_variance == 0.0);
}

TEST_CASE("summed_area moments reference: per texel |x~ - x| <= eps_x = gamma (1 + delta_o) + delta_o and |q 2^-B - x| <= e = 2^-(B+1) + eps_x") {
  // Exact scale and offset: the subtraction's relative u (of x <= 1) and the product's half ulp (of
  // x < 1), eps_x = 1.5u.
  CHECK(pn::summed_area_unit_depth_bound(kQuarter) == Approx(1.5 * kU).epsilon(1e-6));
  CHECK(pn::summed_area_moment_texel_bound(kQuarter) == Approx(0x1p-19 + 1.5 * kU).epsilon(1e-7));
  // [1, 100]: the scale float(1/99) adds its own relative error, below u.
  const float scale = static_cast<float>(1.0 / 99.0);
  const pn::MomentsDepthRange hundred{1.0, 100.0, 1.0f, scale};
  const double delta_s = std::fabs(static_cast<double>(scale) * 99.0 - 1.0);
  CHECK(delta_s <= kU);
  CHECK(pn::summed_area_unit_depth_bound(hundred) == Approx(1.5 * kU + delta_s).epsilon(1e-6));
  // A near plane that is no float: delta_o = |0.1 − float(0.1)| / 9.9 adds on.
  const pn::MomentsDepthRange tenth{0.1, 10.0, static_cast<float>(0.1), static_cast<float>(1.0 / 9.9)};
  const double delta_o = std::fabs(0.1 - static_cast<double>(static_cast<float>(0.1))) / 9.9;
  CHECK(pn::summed_area_unit_depth_bound(tenth) > delta_o + 1.5 * kU);
  CHECK(pn::summed_area_unit_depth_bound(tenth) < delta_o + 2.6 * kU);
  CHECK_THROWS(pn::summed_area_unit_depth_bound({5.0, 5.0, 5.0f, 1.0f}));
  CHECK_THROWS(pn::summed_area_unit_depth_bound({-1.0, 5.0, -1.0f, 1.0f}));
  CHECK_THROWS(pn::summed_area_unit_depth_bound({0.0, 1.0, 0.0f, 0.0f}));
  // The bound holds on 2^16 depths from near − 1 to far + 1 (every texel of a 256² ramp), and is
  // not loose: the worst texel comes within a factor 4 of it.
  for (const pn::MomentsDepthRange& r : {hundred, tenth}) {
    pn::Image ramp(256, 256, 1);
    for (int i = 0; i < 256 * 256; ++i)
      ramp.texels[static_cast<size_t>(i)] =
          static_cast<float>(r.near_depth - 1.0 + i * (r.far_depth - r.near_depth + 2.0) / 65536.0);
    const pn::SummedAreaMomentsReference reference(ramp, r);
    INFO("range [" << r.near_depth << ", " << r.far_depth << "]: worst |x~ - x| " << reference.worst_unit_depth_error()
                   << ", bound " << reference.unit_depth_bound());
    CHECK(reference.worst_unit_depth_error() <= reference.unit_depth_bound());
    CHECK(reference.worst_unit_depth_error() > reference.unit_depth_bound() / 4);
    CHECK(reference.worst_texel_error() <= reference.texel_bound());
    CHECK(reference.worst_texel_error() > 0x1p-19 * 0.9);  // some texel lands near half a step
  }
}

TEST_CASE("summed_area moments reference: the fixed table's bounds, worked for the 2x2 hand map") {
  const pn::SummedAreaMomentsReference reference(moments_hand_map(), kQuarter);
  const auto s = reference.sums({0, 0, 2, 2});
  const double rho = 0.5 + 7 * kU * 0x1p18;  // |mean of q − c| <= 1/2 + 7u · 2^18 = 0.609375 (+ u² terms)
  const double step = 0x1p-18;
  const auto a = reference.fixed_arithmetic_bound(s);
  CHECK(a.mean == Approx(kU * 0.625 + 6 * kU * rho * step).epsilon(1e-5));
  CHECK(a.variance == Approx(8 * kU * 0.078125 + 20 * kU * rho * rho * step * step).epsilon(1e-5));
  const double e = 0x1p-19 + 1.5 * kU, sigma = std::sqrt(0.078125);
  const auto b = reference.fixed_bound(s);
  CHECK(b.mean == Approx(a.mean + e).epsilon(1e-5));
  CHECK(b.variance == Approx(a.variance + 2 * sigma * e + e * e).epsilon(1e-5));
  CHECK(b.variance == Approx(1.15e-6).epsilon(0.01));  // 2 σ e dominates: 2 · 0.2795 · 2.00e-6, then 8u · 0.078
}

TEST_CASE("summed_area moments reference: the float table's bound grows with the prefix sums at the corners") {
  // One row of three texels x = 0.25, 0.75, 0.5 (v = −0.25, 0.25, 0): the prefix at the corner
  // (3, 1) went through X + Y − 2 = 2 roundings of A = 0.5; the other corners are 0.
  pn::Image row(3, 1, 1);
  row.at(0, 0) = 1.0f, row.at(1, 0) = 3.0f, row.at(2, 0) = 2.0f;
  const pn::SummedAreaMomentsReference reference(row, kQuarter);
  const auto all = reference.sums({0, 0, 3, 1});
  const double gamma2 = 2 * kU / (1 - 2 * kU);
  CHECK(all.float_corner_abs1 == Approx(0.5).epsilon(1e-8));
  CHECK(all.float_prefix_error1 == Approx(gamma2 * 0.5).epsilon(1e-8));
  CHECK(all.float_corner_abs2 == Approx(0.125).epsilon(1e-8));  // Σ v²
  const auto first = reference.sums({0, 0, 1, 1});               // corner (1, 1): no rounding
  CHECK(first.float_prefix_error1 == 0.0);
  CHECK(first.float_corner_abs1 == Approx(0.25).epsilon(1e-8));
  // The mean's bound for the whole row, by hand: E1 = 3 ε_v + γ2 A + (2u + u²)(A + γ2 A), then over n with
  // the division's 5u and the addition of 1/2.
  const double eps_v = 1.5 * kU + kU / 2, corner = 2 * kU + kU * kU;
  const double e1 = 3 * eps_v + gamma2 * 0.5 + corner * (0.5 + gamma2 * 0.5);
  const double mu1 = 0.0;  // mean x = 0.5
  const double f1 = e1 / 3 + 5 * kU * (mu1 + e1 / 3);
  CHECK(reference.float_bound(all).mean == Approx(f1 + kU * (0.5 + f1)).epsilon(1e-5));
  // Every bound positive where texels are covered, and the float one far larger than the fixed
  // one's arithmetic on a big map's corner (prefix sums of ~10^5 values).
  const pn::Image big(512, 512, 1, 1.0f);
  const pn::SummedAreaMomentsReference large(big, kQuarter);
  const auto corner_texel = large.sums({511, 511, 1, 1});
  CHECK(large.float_bound(corner_texel).mean > 1000 * large.fixed_arithmetic_bound(corner_texel).mean);
}
