// The CPU definition of PCSS's search and filter regions
// (reference/pcss_regions_reference.h) on cases worked by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "reference/pcss_regions_reference.h"

namespace {

// W_n = 2 n tan(45°) = 2 (n = 1, fov = 90°; in double a few ulps off, hence Approx), N = 16, width 2:
//   search width (z = n)      = 16 (d - 1) / d
//   blocker window for z      = 2 (d - z)/d · (1/z)/2 · 16 = 16 (d - z) / (d z)
//   penumbra for blocker dz   = 2 (d - dz)/dz · (1/d)/2 · 16 = 16 (d - dz) / (dz d)
pn::LightModel hand_light(double width = 2.0) {
  pn::LightModel light;
  light.width = width;
  light.near_plane = 1.0;
  light.far_plane = 100.0;
  light.fov_radians = 3.14159265358979323846 / 2.0;
  light.map_size = 16;
  return light;
}

// 16×16 at depth 10, with a 4×4 blocker at depth 2 on [6, 10)².
pn::Image blocker_map() {
  pn::Image map(16, 16, 1, 10.0f);
  for (int y = 6; y < 10; ++y)
    for (int x = 6; x < 10; ++x) map.at(x, y) = 2.0f;
  return map;
}

bool same(const pn::Rect& r, int x, int y, int w, int h) { return r.x == x && r.y == y && r.width == w && r.height == h; }

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

TEST_CASE("pcss_regions reference: the exact square of an infinite side covers the map, of an infinite centre is empty") {
  CHECK(same(pn::pcss_square(3.0, 4.0, kInf, 16, nullptr), 0, 0, 16, 16));   // 64 texels a side, clipped
  CHECK(same(pn::pcss_square(3.7, 4.2, NAN, 16, nullptr), 3, 4, 1, 1));      // NaN side: 0, one texel
  CHECK(same(pn::pcss_square(3.7, 4.2, -5.0, 16, nullptr), 3, 4, 1, 1));     // negative side: 0
  CHECK(pn::pcss_square(kInf, 4.0, 6.0, 16, nullptr).width == 0);            // misses the map: empty
  CHECK(pn::pcss_square(3.0, -kInf, 6.0, 16, nullptr).height == 0);
  CHECK(same(pn::pcss_square(NAN, 4.2, 0.0, 16, nullptr), 0, 4, 1, 1));      // NaN centre: 0
}

TEST_CASE("pcss_regions reference: an entry of side 4.5 at (8.3, 8.3) stands for 5, 8 and 8 texels a side") {
  const pn::RegionEntry e{3.0, 8.3, 8.3, 4.5};
  // Exact: m = round(4.5) = 5, origin floor(8.3 - 2.5 + 0.5) = 6.
  CHECK(same(pn::entry_region(e, 16, pn::RegionMode::exact), 6, 6, 5, 5));
  // Window: l = floor(8.3 - 2.25) = 6, r = ceil(10.55) = 11, w = 6 = 110b rounds up to 8; origin l.
  CHECK(same(pn::entry_region(e, 16, pn::RegionMode::window), 6, 6, 8, 8));
  // Centred: side 8, origin floor(8.3 - 4 + 0.5) = 4.
  CHECK(same(pn::entry_region(e, 16, pn::RegionMode::centred), 4, 4, 8, 8));
}

TEST_CASE("pcss_regions reference: Step 3 reads the square of the exact region's longer side, moved inside the map") {
  // [-2, 4) x [5, 11) clipped to 4 x 6 at (0, 5): the 6 x 6 square at (0, 5) covers it.
  CHECK(same(pn::search_min_square({3.0, 1.0, 8.0, 6.0}, 16), 0, 5, 6, 6));
  // [12, 18) clipped to [12, 16): the 6 x 6 square moves left to x = 10 and still covers it.
  CHECK(same(pn::search_min_square({3.0, 15.0, 8.0, 6.0}, 16), 10, 5, 6, 6));
  // Wholly outside: nothing to read.
  CHECK(pn::search_min_square({3.0, 40.0, 8.0, 6.0}, 16).width == 0);
  // In every region mode: the window of {3, 8.3, 8.3, 4.5} is [6, 14)², but Step 3 reads the exact region,
  // m = round(4.5) = 5 at floor(8.3 - 2.5 + 0.5) = 6: the 5 x 5 square at (6, 6).
  CHECK(same(pn::entry_region({3.0, 8.3, 8.3, 4.5}, 16, pn::RegionMode::window), 6, 6, 8, 8));
  CHECK(same(pn::search_min_square({3.0, 8.3, 8.3, 4.5}, 16), 6, 6, 5, 5));
}

TEST_CASE("pcss_regions reference: the search over a 4x4 blocker at depth 2 shrinks from 12 to 4 texels and stops") {
  const pn::DepthScan scan(blocker_map());
  const pn::RegionReceiver r{8.0f, 8.0f, 4.0f, 1.0f};
  // No refinement: PCSS's width 16 (4 - 1)/4 = 12.
  pn::RegionEntry e = pn::search_entry(scan, hand_light(), r, 0.01, 0);
  CHECK((e.depth == 4.0 && e.x == 8.0 && e.y == 8.0));
  CHECK(e.side == Approx(12.0));
  // One iteration: the 12 x 12 square [2, 14)² holds the blocker, zmin = 2, s' = 16 (4 - 2)/(4 · 2) = 4.
  e = pn::search_entry(scan, hand_light(), r, 0.01, 1);
  CHECK(e.side == Approx(4.0));
  // Then [6, 10)²: zmin = 2 again, s' = 4 is not smaller: stop at 4, however many iterations are allowed.
  CHECK(pn::search_entry(scan, hand_light(), r, 0.01, 8).side == Approx(4.0));
  CHECK(pn::search_entry(scan, hand_light(), r, 0.01, 100).side == Approx(4.0));
  // The window modes find the same blocker here.
  CHECK(pn::search_entry(scan, hand_light(), r, 0.01, 8).side == Approx(4.0));
}

TEST_CASE("pcss_regions reference: lit receivers — in front of every blocker, outside the map, no surface, NaN depth") {
  const pn::DepthScan scan(blocker_map());
  // d = 1.5: width 16 · 0.5 / 1.5 = 5.33, the 5 x 5 square [6, 11)² has zmin 2 >= 1.5 - 0.01: lit, (d, x, y) kept.
  pn::RegionEntry e = pn::search_entry(scan, hand_light(), {8.0f, 8.0f, 1.5f, 1.0f}, 0.01, 8);
  CHECK((e.lit() && e.side == pn::kRegionLit && e.depth == 1.5 && e.x == 8.0));
  // Bias 0 and a receiver at the blocker's own depth: a texel at exactly d - bias does not occlude.
  CHECK(pn::search_entry(scan, hand_light(), {8.0f, 8.0f, 2.0f, 1.0f}, 0.0, 8).lit());
  // Outside the map: the exact region is empty, nothing can shadow the receiver: lit.
  CHECK(pn::search_entry(scan, hand_light(), {40.0f, 8.0f, 12.0f, 1.0f}, 0.01, 8).lit());
  // No surface, NaN depth: (0, 0, 0, lit).
  e = pn::search_entry(scan, hand_light(), {8.0f, 8.0f, 4.0f, 0.0f}, 0.01, 8);
  CHECK((e.lit() && e.depth == 0.0 && e.x == 0.0));
  CHECK(pn::search_entry(scan, hand_light(), {8.0f, 8.0f, kNan, 1.0f}, 0.01, 8).lit());
  // Refinement off decides nothing: even the receiver in front is not marked lit.
  CHECK_FALSE(pn::search_entry(scan, hand_light(), {8.0f, 8.0f, 1.5f, 1.0f}, 0.01, 0).lit());
}

TEST_CASE("pcss_regions reference: a zero-size light searches one texel, the one under the receiver") {
  const pn::DepthScan scan(blocker_map());
  // Width 0: the 1 x 1 square at (floor u, floor v). Over the blocker: zmin 2 < 4, s' = 0, stop at 0.
  const pn::RegionEntry e = pn::search_entry(scan, hand_light(0.0), {7.5f, 9.9f, 4.0f, 1.0f}, 0.01, 8);
  CHECK((!e.lit() && e.side == 0.0));
  // Next to it, (10.2, 8): texel (10, 8) is at depth 10 >= 4: lit.
  CHECK(pn::search_entry(scan, hand_light(0.0), {10.2f, 8.0f, 4.0f, 1.0f}, 0.01, 8).lit());
}

TEST_CASE("pcss_regions reference: Step 3 reads the blocker on the +u/+v side that the literal window misses") {
  // One texel at the near plane (depth 1) at (12, 12); receiver (8.6, 8.6) at d = 2: width 16 (2 - 1)/2 = 8.
  pn::Image map(16, 16, 1, 10.0f);
  map.at(12, 12) = 1.0f;
  const pn::DepthScan scan(map);
  const pn::RegionReceiver r{8.6f, 8.6f, 2.0f, 1.0f};
  // Step 3: m = 8, origin floor(8.6 - 4 + 0.5) = 5: [5, 13)² holds (12, 12); zmin 1, s' = 16 (2 - 1)/(2 · 1) = 8: stop.
  const pn::RegionEntry searched = pn::search_entry(scan, hand_light(), r, 0.01, 1);
  CHECK(!searched.lit());
  CHECK(searched.side == Approx(8.0));
  // The literal window: l = floor(4.6) = 4, r = ceil(12.6) = 13, w = 10 = 1010b rounds down to 8: [4, 12)² misses
  // column 12 — read for the lit decision (issue 11), it marked this receiver lit.
  CHECK(same(pn::entry_region(searched, 16, pn::RegionMode::window), 4, 4, 8, 8));
  // Centred: side 8, origin floor(8.6 - 4 + 0.5) = 5: [5, 13)² holds it.
  CHECK(same(pn::entry_region(searched, 16, pn::RegionMode::centred), 5, 5, 8, 8));
  // And the texel can shadow the receiver: its own window, 8 texels, is [5, 13)² too.
  CHECK(pn::shadowing_blocker(scan, hand_light(), r, 0.01));
}

TEST_CASE("pcss_regions reference: a texel in the search square shadows only from within its own blocker window") {
  // The same texel at depth 1.5: window 16 (2 - 1.5)/(2 · 1.5) = 2.67 -> 3 texels, [7, 10)²: (12, 12) cannot shadow.
  pn::Image map(16, 16, 1, 10.0f);
  map.at(12, 12) = 1.5f;
  const pn::DepthScan scan(map);
  CHECK_FALSE(pn::shadowing_blocker(scan, hand_light(), {8.6f, 8.6f, 2.0f, 1.0f}, 0.01));
  // Under the receiver it does; a receiver in front of it (d = 1.4) is shadowed by nothing.
  CHECK(pn::shadowing_blocker(scan, hand_light(), {12.5f, 12.5f, 2.0f, 1.0f}, 0.01));
  CHECK_FALSE(pn::shadowing_blocker(scan, hand_light(), {12.5f, 12.5f, 1.4f, 1.0f}, 0.01));
  // NaN and infinite texels are no occluder.
  map.at(12, 12) = -std::numeric_limits<float>::infinity();
  CHECK_FALSE(pn::shadowing_blocker(pn::DepthScan(map), hand_light(), {12.5f, 12.5f, 2.0f, 1.0f}, 0.01));
}

TEST_CASE("pcss_regions reference: rounding decisions within the margin are flagged ambiguous") {
  const pn::DepthScan scan(blocker_map());
  // Bias 0.01 and the blocker at exactly d - bias = 2: the float subtraction may decide it either way.
  pn::Rounding rounding{1e-5};
  pn::search_entry(scan, hand_light(), {8.0f, 8.0f, 2.01f, 1.0f}, 0.01, 8, &rounding);
  CHECK(rounding.ambiguous);
  // The 4x4 blocker case decides nothing near a flip.
  pn::Rounding clear{1e-5};
  pn::search_entry(scan, hand_light(), {8.0f, 8.0f, 4.0f, 1.0f}, 0.01, 8, &clear);
  CHECK_FALSE(clear.ambiguous);
}

TEST_CASE("pcss_regions reference: the filter side is c times the penumbra; no blocker or a lit search is lit") {
  const pn::RegionEntry search{4.0, 8.0, 8.0, 4.0};
  // Penumbra 16 (4 - 2)/(2 · 4) = 4 texels; c = 2: 8.
  CHECK(pn::filter_entry(hand_light(), search, 2.0, true, 1.0).side == Approx(4.0));
  CHECK(pn::filter_entry(hand_light(), search, 2.0, true, 2.0).side == Approx(8.0));
  const pn::RegionEntry none = pn::filter_entry(hand_light(), search, 2.0, false, 1.0);
  CHECK((none.lit() && none.depth == 4.0 && none.x == 8.0));
  CHECK(pn::filter_entry(hand_light(), {4.0, 8.0, 8.0, pn::kRegionLit}, 2.0, true, 1.0).lit());
  // Degenerate: a blocker at or behind the receiver, a NaN mean, a zero-size light, a negative or NaN scale: 0.
  CHECK(pn::filter_entry(hand_light(), search, 4.0, true, 1.0).side == 0.0);
  CHECK(pn::filter_entry(hand_light(), search, NAN, true, 1.0).side == 0.0);
  CHECK(pn::filter_entry(hand_light(0.0), search, 2.0, true, 1.0).side == 0.0);
  CHECK(pn::filter_entry(hand_light(), search, 2.0, true, -1.0).side == 0.0);
  CHECK(pn::filter_entry(hand_light(), search, 2.0, true, NAN).side == 0.0);
}
