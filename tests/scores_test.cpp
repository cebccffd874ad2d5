// Scores on the pixels a viewer sees (metrics/scores.h): mean absolute error
// by hand, masked SSIM against the unmasked definition, the light-facing mask
// from the surface pass's N·L, and where a difference counts.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/error.h"
#include "metrics/scores.h"
#include "metrics/ssim.h"

namespace {

pn::Image noise(int n, unsigned seed) {
  pn::Image out(n, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) out.at(x, y) = static_cast<float>(((x * 73 + y * 151 + seed * 977) % 101) / 100.0);
  return out;
}

// Surface pass image: albedo grey, N·L = facing ? 0.5 : 0.
pn::Image surface(int n, bool (*facing)(int x, int y)) {
  pn::Image out(n, n, 4, 0.5f);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) out.at(x, y, 3) = facing(x, y) ? 0.5f : 0.0f;
  return out;
}

}  // namespace

TEST_CASE("mean absolute error: by hand over all texels and over a mask") {
  pn::Image a(2, 2), b(2, 2), mask(2, 2);
  a.texels = {0.0f, 1.0f, 0.5f, 0.25f};
  b.texels = {1.0f, 1.0f, 0.0f, 0.25f};
  mask.texels = {1.0f, 0.0f, 1.0f, 0.0f};
  CHECK(pn::mean_absolute_error(a, b) == Approx((1.0 + 0.0 + 0.5 + 0.0) / 4).epsilon(1e-12));
  CHECK(pn::mean_absolute_error(a, b, &mask) == Approx((1.0 + 0.5) / 2).epsilon(1e-12));
  const pn::Image none(2, 2);
  CHECK(pn::mean_absolute_error(a, b, &none) == 0.0);
  CHECK_THROWS_AS(pn::mean_absolute_error(a, pn::Image(3, 2)), pn::Error);
}

TEST_CASE("bias errors: darkening where the reference is fully lit, brightening where fully shadowed") {
  pn::Image reference(5, 1), observed(5, 1), mask(5, 1, 1, 1.0f);
  const float r[] = {1.0f, 0.995f, 0.0f, 0.5f, 0.0f}, o[] = {0.8f, 1.0f, 0.3f, 0.2f, 0.0f};
  for (int x = 0; x < 5; ++x) reference.at(x, 0) = r[x], observed.at(x, 0) = o[x];
  const pn::BiasErrors all = pn::bias_errors(reference, observed);
  CHECK(all.acne == Approx((0.2 + 0.0) / 2).epsilon(1e-6));  // the brighter one counts 0, not -0.005
  CHECK(all.leak == Approx((0.3 + 0.0) / 2).epsilon(1e-6));  // 0.5 is neither
  mask.at(0, 0) = 0.0f, mask.at(2, 0) = 0.0f;
  const pn::BiasErrors masked = pn::bias_errors(reference, observed, &mask);
  CHECK(masked.acne == 0.0);
  CHECK(masked.leak == 0.0);
  CHECK_THROWS_AS(pn::bias_errors(reference, pn::Image(3, 1)), pn::Error);
}

TEST_CASE("masked SSIM: an all-ones mask gives the unmasked SSIM, a mask over identical content gives 1") {
  const pn::Image a = noise(40, 1), b = noise(40, 2);
  CHECK(pn::ssim(a, b, pn::Image(40, 40, 1, 1.0f)) == Approx(pn::ssim(a, b)).epsilon(1e-12));
  pn::Image c = a;
  for (int y = 0; y < 40; ++y)
    for (int x = 20; x < 40; ++x) c.at(x, y) = b.at(x, y);  // right half differs
  pn::Image left(40, 40);
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 14; ++x) left.at(x, y) = 1.0f;  // windows (radius 5) of x <= 13 see only the left half
  CHECK(pn::ssim(a, c, left) == Approx(1.0).epsilon(1e-12));
  CHECK(pn::ssim(a, c) < 0.9);
  CHECK_THROWS_AS(pn::ssim(a, c, pn::Image(39, 40)), pn::Error);
}

TEST_CASE("scores: a difference on a surface facing away counts in the whole map, not on light-facing pixels") {
  const int n = 32;
  const pn::Image s = surface(n, [](int x, int) { return x < 16; });
  const pn::Image facing = pn::light_facing_mask(s);
  CHECK(facing.at(3, 3) == 1.0f);
  CHECK(facing.at(20, 3) == 0.0f);
  const pn::Image reference = noise(n, 3);
  pn::Image observed = reference;
  observed.at(25, 10) += 0.5f;  // facing away
  const pn::Scores same = pn::score_visibility(reference, reference, s);
  CHECK((same.whole.ssim == Approx(1.0) && same.light_facing.ssim == Approx(1.0) && same.lit.ssim == Approx(1.0)));
  CHECK((same.whole.mae == 0.0 && same.light_facing.mae == 0.0 && same.lit.mae == 0.0));
  const pn::Scores away = pn::score_visibility(reference, observed, s);
  CHECK(away.whole.mae == Approx(0.5 / (n * n)).epsilon(1e-6));
  CHECK(away.light_facing.mae == 0.0);
  CHECK(away.whole.ssim < 1.0);
}
