// The lit picture's formula by hand: sky where nothing is seen, and
// albedo x (0.25 + 0.75 x cos x visibility) elsewhere.
#include <catch2/catch.hpp>

#include "core/error.h"
#include "metrics/lit_image.h"

TEST_CASE("lit image: sky where the surface is all 0; albedo x (ambient + 0.75 cos vis) elsewhere, by hand") {
  pn::Image surface(4, 1, 4, 0.0f), visibility(4, 1, 1, 1.0f);
  const float cases[3][3] = {{1.0f, 1.0f, 0.8f}, {1.0f, 0.0f, 0.2f}, {0.5f, 0.5f, 0.35f}};  // cos, vis, 0.8 x light
  for (int x = 1; x < 4; ++x) {
    for (int c = 0; c < 3; ++c) surface.at(x, 0, c) = 0.8f;
    surface.at(x, 0, 3) = cases[x - 1][0];
    visibility.at(x, 0) = cases[x - 1][1];
  }
  const pn::Image lit = pn::compose_lit_image(surface, visibility);
  REQUIRE(lit.channels == 3);
  for (int c = 0; c < 3; ++c) {
    CHECK(lit.at(0, 0, c) == pn::kSkyColour[c]);
    for (int x = 1; x < 4; ++x) CHECK(lit.at(x, 0, c) == Approx(cases[x - 1][2]).margin(1e-6));
  }
}

TEST_CASE("lit image: a surface facing away (cos 0) is ambient, not sky; NaN visibility counts as 0") {
  pn::Image surface(2, 1, 4, 0.0f), visibility(2, 1, 1, std::nanf(""));
  for (int x = 0; x < 2; ++x) surface.at(x, 0, 0) = 0.4f, surface.at(x, 0, 1) = 0.4f, surface.at(x, 0, 2) = 0.4f;
  surface.at(1, 0, 3) = 1.0f;
  const pn::Image lit = pn::compose_lit_image(surface, visibility);
  CHECK(lit.at(0, 0, 0) == Approx(0.1f));
  CHECK(lit.at(1, 0, 0) == Approx(0.1f));
}

TEST_CASE("negative: a lit image from images of different sizes or channel counts is refused") {
  CHECK_THROWS_WITH(pn::compose_lit_image(pn::Image(4, 4, 4), pn::Image(4, 3, 1)),
                    Catch::Contains("surface 4x4x4 and visibility 4x3x1"));
  CHECK_THROWS_AS(pn::compose_lit_image(pn::Image(4, 4, 3), pn::Image(4, 4, 1)), pn::Error);
}
