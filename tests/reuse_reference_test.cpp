// The reuse reference by hand: Eq. 7 with the larger value as divisor, the link rules, root finding.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/error.h"
#include "reference/reuse_reference.h"

namespace {
bool similar(float d1, float x1, float y1, float s1, float d2, float x2, float y2, float s2,
             const pn::ReuseParams& p = {}) {
  const float a[4] = {d1, x1, y1, s1}, b[4] = {d2, x2, y2, s2};
  return pn::reuse_similar(a, b, p);
}
}  // namespace

TEST_CASE("Eq. 7 divides by the larger value, so the test is symmetric") {
  // |10 - 9| / 10 = 0.1 <= 0.1, either way round (dividing by 9 would give 0.111).
  CHECK(similar(0.5f, 10, 5, 8, 0.5f, 9, 5, 8));
  CHECK(similar(0.5f, 9, 5, 8, 0.5f, 10, 5, 8));
  CHECK_FALSE(similar(0.5f, 10, 5, 8, 0.5f, 8.9f, 5, 8));
  // sigma1 = 0: sides must be equal.
  CHECK_FALSE(similar(0.5f, 10, 5, 8, 0.5f, 10, 5, 16));
  // depth: |0.5 - 0.56| / 0.56 = 0.107 > 0.1.
  CHECK_FALSE(similar(0.5f, 10, 5, 8, 0.56f, 10, 5, 8));
}

TEST_CASE("zero divisors: equal only when both values are zero; NaN is never similar") {
  CHECK(similar(0.5f, 0, 0, 0, 0.5f, 0, 0, 0));
  CHECK_FALSE(similar(0.5f, 0, 5, 8, 0.5f, 0.01f, 5, 8));
  CHECK_FALSE(similar(std::nanf(""), 1, 1, 1, std::nanf(""), 1, 1, 1));
}

TEST_CASE("links: left when x mod k != 0 and similar, else top when y mod k != 0, never across a tile") {
  // A 4x4 map, tile 2, all entries equal: every pixel not on a tile's left
  // column links left, the others link up unless on a tile's top row.
  pn::Image e(4, 4, 4, 1.0f);
  const auto parents = pn::reuse_parents(e, {0.0f, 0.1f, 0.1f, 2});
  const int expected[16] = {-1, 0, -1, 2,   //
                            0,  4, 2,  6,   //
                            -1, 8, -1, 10,  //
                            8,  12, 10, 14};
  for (int i = 0; i < 16; ++i) {
    INFO("pixel " << i);
    CHECK(parents[static_cast<size_t>(i)] == expected[i]);
  }
  const auto roots = pn::reuse_roots(parents);
  CHECK(roots[5] == 0);
  CHECK(roots[15] == 10);
  CHECK(roots[7] == 2);
}

TEST_CASE("a dissimilar left neighbour falls back to the top one") {
  pn::Image e(2, 2, 4, 1.0f);
  e.at(0, 1, 0) = 5.0f;  // the left neighbour of (1, 1) differs in depth
  const auto parents = pn::reuse_parents(e, {0.0f, 0.1f, 0.1f, 4});
  CHECK(parents[3] == 1);   // (1, 1) -> top (1, 0)
  CHECK(parents[2] == -1);  // (0, 1) differs from (0, 0): a representative
}

TEST_CASE("negative: reuse parameters out of range are refused") {
  CHECK_THROWS_WITH((pn::ReuseParams{-0.1f, 0.1f, 0.1f, 4}.validate()), Catch::Contains("reuse sigma1 -0.1"));
  CHECK_THROWS_WITH((pn::ReuseParams{0.0f, std::nanf(""), 0.1f, 4}.validate()), Catch::Contains("reuse sigma2 nan"));
  CHECK_THROWS_WITH((pn::ReuseParams{0.0f, 0.1f, 0.1f, 0}.validate()), Catch::Contains("reuse tile 0"));
  CHECK_THROWS_WITH((pn::ReuseParams{0.0f, 0.1f, 0.1f, 17}.validate()), Catch::Contains("from 1 to 16"));
}
