// The declared fixtures: sizes from 1×1 up, determinism, and the patterns' defining values.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include "core/error.h"
#include "fixture_images/texture_fixture.h"

TEST_CASE("every fixture generates at every check size, including 1x1 and non-powers of two") {
  for (const auto& f : pn::fixtures::kTextureFixtures) {
    for (const auto& s : pn::fixtures::kCheckSizes) {
      const pn::Image a = pn::generate_fixture(f, s.width, s.height);
      const pn::Image b = pn::generate_fixture(f, s.width, s.height);
      INFO(f.name << " " << s.width << "x" << s.height);
      CHECK(a.width == s.width);
      CHECK(a.height == s.height);
      CHECK(a.texels.size() == static_cast<size_t>(s.width * s.height));
      CHECK(std::memcmp(a.texels.data(), b.texels.data(), a.texels.size() * sizeof(float)) == 0);
    }
  }
}

TEST_CASE("pattern values: constant, ramp ends, step edge, checker cells, impulse centre") {
  using pn::find_fixture;
  const pn::Image c = pn::generate_fixture(find_fixture("constant"), 5, 3);
  for (float v : c.texels) CHECK(v == 0.625f);
  const pn::Image r = pn::generate_fixture(find_fixture("ramp"), 17, 9);
  CHECK(r.at(0, 0) == 0.1f);
  CHECK(r.at(16, 8) == Approx(0.9f).epsilon(1e-6));
  const pn::Image s = pn::generate_fixture(find_fixture("step_edge"), 6, 2);
  CHECK(s.at(2, 1) == 0.25f);
  CHECK(s.at(3, 0) == 0.75f);
  const pn::Image k = pn::generate_fixture(find_fixture("checker"), 7, 7);
  CHECK(k.at(0, 0) == 0.2f);
  CHECK(k.at(3, 0) == 0.8f);
  CHECK(k.at(3, 3) == 0.2f);
  const pn::Image i = pn::generate_fixture(find_fixture("impulse"), 5, 4);
  CHECK(i.at(2, 2) == 1.0f);
  CHECK(i.at(2, 1) == 0.0f);
  const pn::Image one = pn::generate_fixture(find_fixture("ramp"), 1, 1);
  CHECK(one.at(0, 0) == 0.1f);
}

TEST_CASE("seeded noise lies in [a, b) and does not depend on the image size") {
  const auto& noise = pn::find_fixture("noise");
  const pn::Image small = pn::generate_fixture(noise, 3, 5);
  const pn::Image big = pn::generate_fixture(noise, 64, 64);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 3; ++x) CHECK(small.at(x, y) == big.at(x, y));
  for (float v : big.texels) {
    CHECK(v >= 0.0f);
    CHECK(v < 1.0f);
  }
}

TEST_CASE("the nonfinite fixture holds NaN, +Inf and -Inf at about one texel in eight") {
  const pn::Image img = pn::generate_fixture(pn::find_fixture("nonfinite"), 64, 64);
  int nan = 0, pos = 0, neg = 0;
  for (float v : img.texels) {
    nan += std::isnan(v);
    pos += std::isinf(v) && v > 0;
    neg += std::isinf(v) && v < 0;
  }
  CHECK(nan > 0);
  CHECK(pos > 0);
  CHECK(neg > 0);
  const double fraction = double(nan + pos + neg) / img.texels.size();
  CHECK(fraction > 0.08);
  CHECK(fraction < 0.17);
}

TEST_CASE("negative: a 0x0 fixture and an unknown fixture name are refused") {
  CHECK_THROWS_AS(pn::generate_fixture(pn::find_fixture("noise"), 0, 4), pn::Error);
  CHECK_THROWS_WITH(pn::find_fixture("plasma"), Catch::Contains("expected one of constant"));
}

TEST_CASE("boxes: ground from b at the top towards the middle of [a, b] at the bottom, boxes nearer than the ground") {
  const auto& f = pn::find_fixture("boxes");
  const pn::Image img = pn::generate_fixture(f, 128, 128);
  int nearer = 0;
  for (int y = 0; y < 128; ++y) {
    const float ground = f.b - 0.5f * (f.b - f.a) * (static_cast<float>(y) / 127.0f);
    for (int x = 0; x < 128; ++x) {
      const float d = img.at(x, y);
      CHECK(d <= ground);
      CHECK(d >= f.a);
      nearer += d < ground;
    }
  }
  CHECK(nearer > 128 * 128 / 20);  // the boxes cover a visible part of the map
  CHECK(nearer < 128 * 128 / 2);
}
