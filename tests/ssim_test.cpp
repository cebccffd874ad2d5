// SSIM's own properties (its values are checked against scikit-image by the ssim_vs_skimage test).
#include <catch2/catch.hpp>

#include <cmath>

#include "core/error.h"
#include "fixture_images/texture_fixture.h"
#include "metrics/ssim.h"

TEST_CASE("SSIM of an image with itself is 1, and symmetric") {
  const pn::Image a = pn::generate_fixture(pn::find_fixture("noise"), 40, 30);
  const pn::Image b = pn::generate_fixture(pn::find_fixture("boxes"), 40, 30);
  CHECK(pn::ssim(a, a) == Approx(1.0).epsilon(1e-12));
  CHECK(pn::ssim(a, b) == Approx(pn::ssim(b, a)).epsilon(1e-12));
  CHECK(pn::ssim(a, b) < 0.5);
}

TEST_CASE("SSIM of two constants by hand: (2ab + C1) / (a^2 + b^2 + C1), variances 0") {
  const pn::Image a(11, 11, 1, 0.2f), b(11, 11, 1, 0.6f);
  const double c1 = 0.01 * 0.01, x = 0.2f, y = 0.6f;
  CHECK(pn::ssim(a, b) == Approx((2 * x * y + c1) / (x * x + y * y + c1)).epsilon(1e-12));
}

TEST_CASE("negative: SSIM refuses different sizes, images smaller than the window and non-finite values") {
  CHECK_THROWS_WITH(pn::ssim(pn::Image(12, 12), pn::Image(12, 13)), Catch::Contains("expected two single-channel images of the same size"));
  CHECK_THROWS_WITH(pn::ssim(pn::Image(10, 40), pn::Image(10, 40)), Catch::Contains("expected at least 11x11"));
  pn::Image nan(11, 11);
  nan.at(3, 4) = std::nanf("");
  CHECK_THROWS_WITH(pn::ssim(nan, pn::Image(11, 11)), Catch::Contains("non-finite value at texel 47"));
}
