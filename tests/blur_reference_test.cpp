// The CPU blur reference against values worked out by hand from the definition.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "reference/blur_reference.h"

TEST_CASE("normalised Gaussian weights: radius 1, sigma 1 by hand") {
  const double e = std::exp(-0.5);
  const auto w = pn::normalised_gaussian(1, 1.0);
  REQUIRE(w.size() == 3);
  CHECK(w[0] == Approx(e / (1 + 2 * e)).epsilon(1e-15));
  CHECK(w[1] == Approx(1 / (1 + 2 * e)).epsilon(1e-15));
  CHECK(w[2] == w[0]);
}

TEST_CASE("an interior impulse blurs into the outer product of the 1-D weights") {
  pn::Image impulse(9, 9);
  impulse.at(4, 4) = 1.0f;
  const pn::BlurParams params{2, 0.8, false, 0.0};
  const pn::Image out = pn::blur_reference(impulse, params);
  auto g = [](int i) { return std::exp(-0.5 * (i / 0.8) * (i / 0.8)); };
  const double sum = g(-2) + g(-1) + g(0) + g(1) + g(2);
  for (int y = 2; y <= 6; ++y)
    for (int x = 2; x <= 6; ++x) CHECK(out.at(x, y) == Approx(g(x - 4) * g(y - 4) / (sum * sum)).epsilon(1e-6));
  CHECK(out.at(1, 4) == 0.0f);
}

TEST_CASE("clamped edges: a constant image stays constant, a 1x1 image is unchanged") {
  pn::Image c(3, 5, 1, 0.3f);
  for (float v : pn::blur_reference(c, {3, 1.0, false, 0.0}).texels) CHECK(v == Approx(0.3f).epsilon(1e-6));
  pn::Image one(1, 1, 1, 7.0f);
  CHECK(pn::blur_reference(one, {7, 3.0, false, 0.0}).at(0, 0) == Approx(7.0f));
}

TEST_CASE("edge clamping repeats the border texel: left column of a 1-D step") {
  pn::Image step(4, 1);
  step.at(0, 0) = 1.0f;  // 1 0 0 0
  const auto w = pn::normalised_gaussian(1, 1.0);
  // out(0) = w[-1]*v(clamp(-1)=0) + w[0]*v(0) + w[1]*v(1) = w0 + w1 (vertical taps all clamp to row 0)
  CHECK(pn::blur_reference(step, {1, 1.0, false, 0.0}).at(0, 0) == Approx(w[0] + w[1]).epsilon(1e-6));
}

TEST_CASE("non-finite texels read as the documented substitute value") {
  pn::Image img(3, 1, 1, 1.0f);
  img.at(1, 0) = std::numeric_limits<float>::quiet_NaN();
  const auto w = pn::normalised_gaussian(1, 1.0);
  const pn::Image out = pn::blur_reference(img, {1, 1.0, false, 0.0});
  CHECK(out.at(1, 0) == Approx(w[0] + w[2] + w[1] * pn::kBlurNonfiniteValue).epsilon(1e-6));
  for (float v : out.texels) CHECK(std::isfinite(v));
}

TEST_CASE("depth-aware: taps on another surface are dropped and the rest renormalised") {
  pn::Image value(3, 1), depth(3, 1);
  value.at(0, 0) = 1.0f, value.at(1, 0) = 2.0f, value.at(2, 0) = 4.0f;
  depth.at(0, 0) = 1.0f, depth.at(1, 0) = 1.01f, depth.at(2, 0) = 5.0f;
  const pn::BlurParams params{1, 1.0, true, 0.05};
  const double e = std::exp(-0.5);
  // Centre x=1: x=0 same surface, x=2 not: (e*1 + 1*2) / (e + 1); the vertical pass is the identity on one row.
  CHECK(pn::blur_depth_aware_reference(value, depth, params).at(1, 0) == Approx((e * 1 + 2) / (e + 1)).epsilon(1e-6));
}

TEST_CASE("negative: blur parameters out of range are refused, naming the parameter") {
  CHECK_THROWS_WITH((pn::BlurParams{17, 1.0, false, 0.0}.validate()), Catch::Contains("blur radius 17"));
  CHECK_THROWS_WITH((pn::BlurParams{-1, 1.0, false, 0.0}.validate()), Catch::Contains("expected an integer from 0"));
  CHECK_THROWS_WITH((pn::BlurParams{3, 0.0, false, 0.0}.validate()), Catch::Contains("blur sigma 0"));
  CHECK_THROWS_WITH((pn::BlurParams{3, std::nan(""), false, 0.0}.validate()), Catch::Contains("blur sigma nan"));
  CHECK_THROWS_WITH((pn::BlurParams{3, 1.0, true, -0.1}.validate()), Catch::Contains("depth tolerance -0.1"));
}
