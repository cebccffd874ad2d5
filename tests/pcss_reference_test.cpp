// The exact-PCSS CPU reference on cases worked by hand, and the technique
// settings' parsing and validation.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.h"
#include "pipeline/pcss_settings.h"
#include "reference/pcss_reference.h"

namespace {

// A light whose widths are easy by hand: W_n = 2 n tan(fov/2) = 2 (n = 1, fov = 90°),
// N = 16, width 2: search width (z = n) = 2 (dP - 1)/dP · 1/2 · 16 = 16 (dP - 1)/dP;
// penumbra = 2 (dP - dz)/dz · (1/dP)/2 · 16 = 16 (dP - dz)/(dz dP).
pn::LightModel hand_light() {
  pn::LightModel light;
  light.width = 2.0;
  light.near_plane = 1.0;
  light.far_plane = 100.0;
  light.fov_radians = 3.14159265358979 / 2.0;
  light.map_size = 16;
  return light;
}

pn::Image one_receiver(double u, double v, double depth) {
  pn::Image g(1, 1, 4);
  g.at(0, 0, 0) = static_cast<float>(u);
  g.at(0, 0, 1) = static_cast<float>(v);
  g.at(0, 0, 2) = static_cast<float>(depth);
  g.at(0, 0, 3) = 1.0f;
  return g;
}

}  // namespace

TEST_CASE("pcss square: n = round(s) texels whose centres are nearest the centre, clipped") {
  double margin = 0;
  pn::Rect r = pn::pcss_square(3.7, 3.2, 0.0, 16, &margin);  // one texel: the one containing the point
  CHECK((r.x == 3 && r.y == 3 && r.width == 1 && r.height == 1));
  r = pn::pcss_square(3.7, 3.7, 2.0, 16, &margin);  // centres 3.5 and 4.5 are nearest 3.7
  CHECK((r.x == 3 && r.width == 2));
  r = pn::pcss_square(1.0, 8.0, 6.0, 16, &margin);  // [-2, 4) clipped to [0, 4)
  CHECK((r.x == 0 && r.width == 4 && r.y == 5 && r.height == 6));
  r = pn::pcss_square(40.0, 8.0, 6.0, 16, &margin);  // wholly outside: empty
  CHECK(r.width == 0);
  pn::pcss_square(8.3, 8.3, 4.5001, 16, &margin);  // s just above a rounding point, origins 6.3
  CHECK(margin == Approx(0.0001).margin(1e-9));
}

TEST_CASE("exact PCSS reference: a 4x4 blocker at depth 2 over a receiver at depth 4") {
  pn::Image map(16, 16, 1, 10.0f);  // receivers' plane far behind
  for (int y = 6; y < 10; ++y)
    for (int x = 6; x < 10; ++x) map.at(x, y) = 2.0f;
  // Search width 16 (4 - 1)/4 = 12: the 12x12 square around (8, 8) holds all 16 blocker texels,
  // blocker mean 2; penumbra 16 (4 - 2)/(2 · 4) = 4: the 4x4 square [6, 10)² is all blocker.
  pn::PcssReference r = pn::exact_pcss_reference(map, one_receiver(8.0, 8.0, 4.0), hand_light(), 0.01, 1.0, 1e-4);
  CHECK(r.visibility.at(0, 0) == 0.0f);
  // Centre (10, 8): filter square [8, 12) x [6, 10): half of it is blocker.
  r = pn::exact_pcss_reference(map, one_receiver(10.0, 8.0, 4.0), hand_light(), 0.01, 1.0, 1e-4);
  CHECK(r.visibility.at(0, 0) == 0.5f);
  // c = 2: filter 8x8 = [6, 14) x [4, 12): 16 of 64 texels occlude.
  r = pn::exact_pcss_reference(map, one_receiver(10.0, 8.0, 4.0), hand_light(), 0.01, 2.0, 1e-4);
  CHECK(r.visibility.at(0, 0) == 0.75f);
  // A receiver in front of the blocker, a pixel without a surface, a NaN depth: lit.
  CHECK(pn::exact_pcss_reference(map, one_receiver(8.0, 8.0, 1.5), hand_light(), 0.01, 1.0, 1e-4).visibility.at(0, 0) == 1.0f);
  pn::Image nothing = one_receiver(8.0, 8.0, 4.0);
  nothing.at(0, 0, 3) = 0.0f;
  CHECK(pn::exact_pcss_reference(map, nothing, hand_light(), 0.01, 1.0, 1e-4).visibility.at(0, 0) == 1.0f);
  CHECK(pn::exact_pcss_reference(map, one_receiver(8.0, 8.0, NAN), hand_light(), 0.01, 1.0, 1e-4).visibility.at(0, 0) == 1.0f);
  // NaN texels are no occluder: the blocker made of NaN shadows nothing.
  pn::Image nan_map = map;
  for (int y = 6; y < 10; ++y)
    for (int x = 6; x < 10; ++x) nan_map.at(x, y) = NAN;
  CHECK(pn::exact_pcss_reference(nan_map, one_receiver(8.0, 8.0, 4.0), hand_light(), 0.01, 1.0, 1e-4).visibility.at(0, 0) == 1.0f);
}

TEST_CASE("PCSS settings: all-off preset and key=value overrides") {
  const pn::PcssSettings off = pn::fast_pcss_all_off();
  CHECK((off.refine_iterations == 0 && off.leaf_side == 1 && off.search_tile == 0 && off.filter_tile == 0 &&
         off.region == pn::RegionMode::exact && !off.blur));
  pn::PcssSettings s = pn::fast_pcss();
  for (const auto& [key, value] : {std::pair{"leaf", "4"}, {"reuse", "off"}, {"region", "centred"}, {"c", "1.5"}})
    pn::set_pcss_setting(s, key, value);
  CHECK((s.leaf_side == 4 && s.search_tile == 0 && s.filter_tile == 0 && s.region == pn::RegionMode::centred &&
         s.filter_scale == 1.5f));
  CHECK_THROWS_WITH(pn::set_pcss_setting(s, "leaf", "x"), "technique 'fast': leaf=x: expected an integer");
  CHECK_THROWS_WITH(pn::set_pcss_setting(s, "colour", "red"), Catch::StartsWith("technique 'fast': unknown setting 'colour': expected refine, region"));
}
