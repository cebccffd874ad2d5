// The literal Steps 1–7 reference on regions worked out by hand from seed 000 §2.2.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <ostream>

#include "reference/region_reference.h"

namespace pn {
std::ostream& operator<<(std::ostream& out, const RegionWindow& w) {
  return out << "{origin (" << w.u << ", " << w.v << "), side " << w.side << ", level " << w.level << "}";
}
}  // namespace pn

using pn::RegionWindow;
using pn::region_reference;

TEST_CASE("a region inside the map: w = 5 (101b, second bit 0) rounds down to 4") {
  // N 8, centre (4, 4), s 3: l = floor(2.5) = 2, r = ceil(5.5) = 6, w = 5 -> 4; x' = 2 + 2 = 4.
  CHECK(region_reference(4, 4, 3, 8) == RegionWindow{2, 2, 4, 2});
}

TEST_CASE("Step 7 pushes a window back inside at the right and bottom edges") {
  // N 8, centre (7, 7), s 4: l = 5, r = ceil(9) -> 7, w = 3 (11b) -> 4; x' = 7, 7 + 2 - 1 >= 8 -> x' = 6.
  CHECK(region_reference(7, 7, 4, 8) == RegionWindow{4, 4, 4, 2});
}

TEST_CASE("w' != h': s' = min(2 min(w', h'), E)") {
  // N 16, centre (1, 8), s 6: w = 5 -> 4 (l clamped to 0), h = 7 (111b) -> 8; s' = min(8, 16) = 8; y' = 5 + 4.
  CHECK(region_reference(1, 8, 6, 16) == RegionWindow{0, 5, 8, 3});
}

TEST_CASE("the cap E (largest power of two <= N) applies when w' = h' exceeds N") {
  // N 100, centre (50, 50), s 200: w = h = 100 (1100100b, second bit 1) -> 128 -> capped to 64.
  CHECK(region_reference(50, 50, 200, 100) == RegionWindow{0, 0, 64, 6});
}

TEST_CASE("a region wholly outside the map becomes the nearest edge texels") {
  // N 8, centre (-20, 3), s 2: l, r clamp to 0 (w = 1); t = 2, b = 4 (h = 3 -> 4); s' = min(2, 8) = 2.
  CHECK(region_reference(-20, 3, 2, 8) == RegionWindow{0, 2, 2, 1});
}

TEST_CASE("side 0 and NaN / negative sides: one texel, or two for a non-integer centre") {
  CHECK(region_reference(3, 3, 0, 8) == RegionWindow{3, 3, 1, 0});
  CHECK(region_reference(3.5f, 3.5f, 0, 8) == RegionWindow{3, 3, 2, 1});
  CHECK(region_reference(3, 3, std::nanf(""), 8) == region_reference(3, 3, 0, 8));
  CHECK(region_reference(3, 3, -5, 8) == region_reference(3, 3, 0, 8));
}

TEST_CASE("centred option: same side, origin round(centre - s'/2) clamped into the map") {
  // N 16, centre (10, 10), s 5: l = 7, r = 13, w = 7 -> 8; literal origin 7, centred round(10 - 4) = 6.
  CHECK(region_reference(10, 10, 5, 16) == RegionWindow{7, 7, 8, 3});
  CHECK(pn::region_centred_reference(10, 10, 5, 16) == RegionWindow{6, 6, 8, 3});
  // N 16, centre (15, 0), s 5: w = 15 - 12 + 1 = 4, h = 3 - 0 + 1 = 4, s' = 4; x: round(13) -> clamped to 12.
  CHECK(pn::region_centred_reference(15, 0, 5, 16) == RegionWindow{12, 0, 4, 2});
}
