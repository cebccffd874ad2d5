// The vsm reference on hand-worked values: a two-depth window's moments, mean,
// variance and Chebyshev bound; the min variance; the reduction; EVSM's warp;
// the window's min/max and the depth-range bound; the exact PCF it bounds.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "reference/vsm_reference.h"

namespace {

// sigma with exp(-1 / (2 sigma^2)) = 1/2: the radius-1 weights are (1/2, 1, 1/2) / 2.
constexpr double kHalfSigma = 0.84932180028801904;

pn::VsmParams half_weights() {
  pn::VsmParams p;
  p.blur.radius = 1;
  p.blur.sigma = kHalfSigma;
  return p;
}

// [0.2 0.6]: at x = 0 the taps -1, 0, +1 read 0.2, 0.2, 0.6 with weights 1/4, 1/2, 1/4.
pn::Image two_texels() {
  pn::Image m(2, 1);
  m.at(0, 0) = 0.2f;
  m.at(1, 0) = 0.6f;
  return m;
}

}  // namespace

TEST_CASE("vsm reference: window moments of [0.2 0.6] at x = 0 (weights 1/4 1/2 1/4) are mean 0.3, E[d^2] 0.12") {
  const pn::Image m = pn::vsm_window_moments_reference(two_texels(), half_weights());
  REQUIRE(m.channels == 2);
  CHECK(m.at(0, 0, 0) == Approx(0.3).epsilon(1e-6));   // 3/4 * 0.2 + 1/4 * 0.6
  CHECK(m.at(0, 0, 1) == Approx(0.12).epsilon(1e-6));  // 3/4 * 0.04 + 1/4 * 0.36
  CHECK(m.at(1, 0, 0) == Approx(0.5).epsilon(1e-6));   // 1/4 * 0.2 + 3/4 * 0.6
  // variance 0.12 - 0.09 = 0.03; at t = 0.5: 0.03 / (0.03 + 0.2^2) = 3/7, above the exact PCF's 1/4
  CHECK(pn::chebyshev_bound(0.3, 0.12, 0.5, 0.0) == Approx(3.0 / 7.0));
  CHECK(pn::gaussian_pcf_visibility(two_texels(), 0, 0, 0.5f, half_weights().blur) == Approx(0.25));
}

TEST_CASE("vsm reference: Chebyshev of half 0.2, half 0.6 (mean 0.4, variance 0.04) at t 0.7 is 4/13") {
  CHECK(pn::chebyshev_bound(0.4, 0.2, 0.7, 0.0) == Approx(4.0 / 13.0));
  // min variance 0.5 relative: max(0.04, 0.5 * 0.16) = 0.08, so 0.08 / (0.08 + 0.09) = 8/17
  CHECK(pn::chebyshev_bound(0.4, 0.2, 0.7, 0.5) == Approx(8.0 / 17.0));
  // at or in front of the mean, and for a NaN receiver: lit
  CHECK(pn::chebyshev_bound(0.4, 0.2, 0.4, 0.0) == 1.0);
  CHECK(pn::chebyshev_bound(0.4, 0.2, 0.1, 0.0) == 1.0);
  CHECK(pn::chebyshev_bound(0.4, 0.2, std::nan(""), 0.0) == 1.0);
  // no variance, mean 0: the floor FLT_MIN, not 0/0 — lit within FLT_MIN of the mean, shadowed beyond
  CHECK(pn::chebyshev_bound(0.0, 0.0, 1e-30, 0.0) == Approx(1.17549435e-38 / (1.17549435e-38 + 1e-60)));
  CHECK(pn::chebyshev_bound(0.0, 0.0, 1e-10, 0.0) < 1e-17);
}

TEST_CASE("vsm reference: two depths, t at the upper one: the bound equals the exact fraction (tight)") {
  // a quarter of the weight at 0.6, the rest at 0.2: mean 0.3, E[d^2] 0.12, P(d >= 0.6) = 1/4
  CHECK(pn::chebyshev_bound(0.3, 0.12, 0.6, 0.0) == Approx(0.25));
}

TEST_CASE("vsm reference: linstep(0.2, 1, p) maps 0.3 to 0.125, 0.1 to 0, 1 to 1; amount 0 is the identity") {
  CHECK(pn::reduce_bleeding(0.3, 0.2) == Approx(0.125));
  CHECK(pn::reduce_bleeding(0.1, 0.2) == 0.0);
  CHECK(pn::reduce_bleeding(1.0, 0.2) == 1.0);
  CHECK(pn::reduce_bleeding(0.37, 0.0) == Approx(0.37));
  CHECK(pn::reduce_bleeding(0.995, 5.0) == Approx(0.5));  // amount clamped to 0.99
}

TEST_CASE("vsm reference: moments of 0.5 are (0.5, 0.25); non-finite depths enter as the far depth") {
  pn::VsmParams p;
  p.far_depth = 2.0f;
  const auto m = pn::vsm_moments(0.5f, p);
  CHECK(m[0] == 0.5);
  CHECK(m[1] == 0.25);
  for (float d : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                  -std::numeric_limits<float>::infinity()}) {
    const auto far = pn::vsm_moments(d, p);
    CHECK(far[0] == 2.0);
    CHECK(far[1] == 4.0);
  }
}

TEST_CASE("evsm reference: depth 1 of range 0..2 warps to x 0.5: exp(4 x) = e^2, -exp(-2 x) = -1/e") {
  pn::VsmParams p;
  p.kind = pn::VsmKind::evsm4;
  p.near_depth = 0.0f;
  p.far_depth = 2.0f;
  p.positive_exponent = 4.0f;
  p.negative_exponent = 2.0f;
  const auto m = pn::vsm_moments(1.0f, p);
  CHECK(m[0] == Approx(std::exp(2.0)));
  CHECK(m[1] == Approx(std::exp(4.0)));
  CHECK(m[2] == Approx(-std::exp(-1.0)));
  CHECK(m[3] == Approx(std::exp(-2.0)));
  CHECK(pn::vsm_moments(-1.0f, p)[0] == 1.0);                                          // in front of near: x = 0
  CHECK(pn::vsm_moments(std::nanf(""), p)[0] == Approx(std::exp(4.0)));                // non-finite: x = 1
  p.positive_exponent = 42.0f;
  CHECK(pn::vsm_moments(2.0f, p)[1] == Approx(std::exp(84.0)));  // the bound: e^84 < FLT_MAX
  CHECK(std::exp(84.0) * 2.0 < std::numeric_limits<float>::max());
}

TEST_CASE("vsm reference: a window's min and max and the depth-range bound's three answers") {
  pn::Image m(3, 3, 1, 0.5f);
  m.at(0, 0) = 0.2f;
  m.at(2, 2) = 0.9f;
  m.at(1, 0) = std::numeric_limits<float>::quiet_NaN();
  const pn::DepthRange whole = pn::window_depth_range(m, 0, 0, 1);  // side 3 pushed inside: the whole map
  CHECK(whole.min == 0.2f);
  CHECK(whole.max == std::numeric_limits<float>::infinity());  // NaN reads as +Inf: no occluder
  const pn::DepthRange one = pn::window_depth_range(m, 2, 2, 0);
  CHECK(one.min == 0.9f);
  CHECK(one.max == 0.9f);
  const pn::DepthRange r{0.2f, 0.6f};
  CHECK(pn::depth_range_bound(r, 0.2f) == PN_VSM_BOUND_LIT);
  CHECK(pn::depth_range_bound(r, std::nextafter(0.2f, 1.0f)) == PN_VSM_BOUND_NONE);
  CHECK(pn::depth_range_bound(r, 0.6f) == PN_VSM_BOUND_NONE);
  CHECK(pn::depth_range_bound(r, std::nextafter(0.6f, 1.0f)) == PN_VSM_BOUND_SHADOWED);
  CHECK(pn::vsm_visibility(PN_VSM_BOUND_NONE, 0.3) == 0.3);
  CHECK(pn::vsm_visibility(PN_VSM_BOUND_SHADOWED, 0.3) == 0.0);
}

TEST_CASE("negative: vsm parameters out of range are refused with one line each") {
  pn::VsmParams p;
  p.positive_exponent = 43.0f;
  CHECK_THROWS_WITH(p.validate(), Catch::Contains("evsm exponent 43: expected 0 to 42"));
  p = {};
  p.bleeding_reduction = 1.0f;
  CHECK_THROWS_WITH(p.validate(), Catch::Contains("vsm bleeding reduction 1: expected 0 to 0.99"));
  p = {};
  p.near_depth = 1.0f;
  CHECK_THROWS_WITH(p.validate(), Catch::Contains("expected near < far"));
  p = {};
  p.min_variance = -1.0f;
  CHECK_THROWS_AS(p.validate(), pn::Error);
}
