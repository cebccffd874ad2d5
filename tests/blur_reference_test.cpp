// The CPU blur reference against values worked out by hand from the definition.
#include <catch2/catch.hpp>

#include <cmath>
#include <initializer_list>
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

namespace {

// A filter-region map (d, x, y, s) with the given sides in channel 3.
pn::Image filter_map(int w, int h, std::initializer_list<float> sides) {
  pn::Image map(w, h, 4);
  int i = 0;
  for (float s : sides) map.at(i % w, i / w, 3) = s, ++i;
  return map;
}

pn::BlurParams adaptive_params(int radius, bool depth_aware, float pixels_per_texel) {
  pn::BlurParams p{radius, 1.0, depth_aware, 0.05};
  p.adaptive = true;
  p.pixels_per_texel = pixels_per_texel;
  return p;
}

}  // namespace

TEST_CASE("adaptive radius: floor(s k / 2) clamped to [0, R]; lit, NaN and contact give 0") {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  CHECK(pn::blur_adaptive_radius(-1.0f, 1.0f, 3) == 0);   // lit (PN_REGION_LIT)
  CHECK(pn::blur_adaptive_radius(nan, 1.0f, 3) == 0);
  CHECK(pn::blur_adaptive_radius(-inf, 1.0f, 3) == 0);
  CHECK(pn::blur_adaptive_radius(0.0f, 1.0f, 3) == 0);    // hard contact
  CHECK(pn::blur_adaptive_radius(1.99f, 1.0f, 3) == 0);   // s < 2/k
  CHECK(pn::blur_adaptive_radius(2.0f, 1.0f, 3) == 1);    // half of 2 pixels
  CHECK(pn::blur_adaptive_radius(5.9f, 1.0f, 3) == 2);
  CHECK(pn::blur_adaptive_radius(6.0f, 1.0f, 3) == 3);
  CHECK(pn::blur_adaptive_radius(1e6f, 1.0f, 3) == 3);    // never above R
  CHECK(pn::blur_adaptive_radius(inf, 1.0f, 3) == 3);
  CHECK(pn::blur_adaptive_radius(3.0f, 2.0f, 3) == 3);    // 2 screen pixels per texel: 6 pixels wide
  CHECK(pn::blur_adaptive_radius(3.0f, 0.5f, 3) == 0);    // 1.5 pixels wide: contact
  CHECK(pn::blur_adaptive_radius(8.0f, 0.5f, 3) == 2);
  CHECK(pn::blur_adaptive_radius(100.0f, 1.0f, 0) == 0);  // R = 0: the identity
  CHECK(pn::blur_adaptive_radius(100.0f, 0.0f, 3) == 0);  // k not > 0
}

TEST_CASE("adaptive blur, 3x1 row by hand: each output takes its own radius, the vertical pass is the identity") {
  // Values 1 2 4; sides 2 (r 1), 0 (contact, r 0), -1 (lit, r 0); k = 1, R = 3.
  pn::Image value(3, 1);
  value.at(0, 0) = 1.0f, value.at(1, 0) = 2.0f, value.at(2, 0) = 4.0f;
  const pn::Image map = filter_map(3, 1, {2.0f, 0.0f, -1.0f});
  const double e = std::exp(-0.5);
  const pn::Image out = pn::blur_adaptive_reference(value, map, nullptr, adaptive_params(3, false, 1.0f));
  // x=0, r 1: taps clamp(-1)=0, 0, 1: (e*1 + 1*1 + e*2) / (1 + 2e). One row: the vertical pass
  // of radius 1 reads the same texel three times, so it returns it.
  CHECK(out.at(0, 0) == Approx((e * 1 + 1 + e * 2) / (1 + 2 * e)).epsilon(1e-6));
  CHECK(out.at(1, 0) == 2.0f);  // radius 0: unchanged, exactly
  CHECK(out.at(2, 0) == 4.0f);
}

TEST_CASE("adaptive blur, 1x3 column by hand: the vertical pass gathers with the output pixel's radius") {
  // Column 1 2 4 (top to bottom); sides -1 (r 0), 4 (r 2), 0 (r 0); k = 1, R = 3.
  // The horizontal pass is the identity on one column; the middle pixel sums
  // taps -2..2 clamped to rows 0, 0, 1, 2, 2: (g2*1 + g1*1 + 2 + g1*4 + g2*4) / (1 + 2 g1 + 2 g2).
  pn::Image value(1, 3);
  value.at(0, 0) = 1.0f, value.at(0, 1) = 2.0f, value.at(0, 2) = 4.0f;
  const pn::Image map = filter_map(1, 3, {-1.0f, 4.0f, 0.0f});
  const double g1 = std::exp(-0.5), g2 = std::exp(-2.0);
  const pn::Image out = pn::blur_adaptive_reference(value, map, nullptr, adaptive_params(3, false, 1.0f));
  CHECK(out.at(0, 0) == 1.0f);
  CHECK(out.at(0, 1) == Approx((g2 + g1 + 2 + 4 * g1 + 4 * g2) / (1 + 2 * g1 + 2 * g2)).epsilon(1e-6));
  CHECK(out.at(0, 2) == 4.0f);
}

TEST_CASE("adaptive depth-aware blur: a tap off the centre's surface is dropped; a sky pixel keeps its value") {
  // Values 1 2 4 8, depths 1, 1.01, 5, +Inf; sides 2 (r 1) everywhere but the sky's (lit).
  pn::Image value(4, 1), depth(4, 1);
  value.at(0, 0) = 1.0f, value.at(1, 0) = 2.0f, value.at(2, 0) = 4.0f, value.at(3, 0) = 8.0f;
  depth.at(0, 0) = 1.0f, depth.at(1, 0) = 1.01f, depth.at(2, 0) = 5.0f;
  depth.at(3, 0) = std::numeric_limits<float>::infinity();
  const pn::Image map = filter_map(4, 1, {2.0f, 2.0f, 2.0f, -1.0f});
  const double e = std::exp(-0.5);
  const pn::Image out = pn::blur_adaptive_reference(value, map, &depth, adaptive_params(3, true, 1.0f));
  CHECK(out.at(1, 0) == Approx((e * 1 + 2) / (e + 1)).epsilon(1e-6));  // x=2 (depth 5) dropped
  CHECK(out.at(2, 0) == 4.0f);  // both neighbours on other surfaces: only the centre
  CHECK(out.at(3, 0) == 8.0f);  // lit sky pixel: radius 0
}

TEST_CASE("negative: the adaptive reference refuses a filter map of another size or without 4 channels") {
  const pn::Image value(3, 2);
  CHECK_THROWS_WITH(pn::blur_adaptive_reference(value, pn::Image(3, 2, 1), nullptr, adaptive_params(3, false, 1.0f)),
                    Catch::Contains("4-channel filter map"));
  CHECK_THROWS_WITH(pn::blur_adaptive_reference(value, pn::Image(2, 3, 4), nullptr, adaptive_params(3, false, 1.0f)),
                    Catch::Contains("of the source's size"));
  CHECK_THROWS_WITH(pn::blur_adaptive_reference(value, pn::Image(3, 2, 4), nullptr, adaptive_params(3, true, 1.0f)),
                    Catch::Contains("expects a depth image"));
}

TEST_CASE("negative: blur parameters out of range are refused, naming the parameter") {
  CHECK_THROWS_WITH((pn::BlurParams{17, 1.0, false, 0.0}.validate()), Catch::Contains("blur radius 17"));
  CHECK_THROWS_WITH((pn::BlurParams{-1, 1.0, false, 0.0}.validate()), Catch::Contains("expected an integer from 0"));
  CHECK_THROWS_WITH((pn::BlurParams{3, 0.0, false, 0.0}.validate()), Catch::Contains("blur sigma 0"));
  CHECK_THROWS_WITH((pn::BlurParams{3, std::nan(""), false, 0.0}.validate()), Catch::Contains("blur sigma nan"));
  CHECK_THROWS_WITH((pn::BlurParams{3, 1.0, true, -0.1}.validate()), Catch::Contains("depth tolerance -0.1"));
  for (float k : {0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    pn::BlurParams p;
    p.adaptive = true;
    p.pixels_per_texel = k;
    CHECK_THROWS_WITH(p.validate(), Catch::Contains("blur pixels per texel") && Catch::Contains("expected a finite number > 0"));
  }
}
