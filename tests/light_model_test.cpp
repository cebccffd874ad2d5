// The light model's widths worked out by similar triangles.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "scene/light_model.h"

namespace {
// Light of width 2 at depth 0, 90° field of view (W_n = 2 n), near 1, N 1024.
pn::LightModel light() { return {2.0, 1.0, 100.0, 1.5707963267948966, 1024}; }
}  // namespace

TEST_CASE("blocker window: rays from a receiver at depth 10 to the light's edges cross depth 5 at x = +-0.5") {
  // World width 1 at depth 5 -> 1 x (1 / 5) = 0.2 at the near plane -> 0.2 / W_n(2) x 1024 = 102.4 texels.
  CHECK(light().blocker_window_texels(10.0, 5.0) == Approx(102.4).epsilon(1e-12));
  // The initial search (z = near): world 2 x 9 / 10 = 1.8 at depth 1 -> 1.8 / 2 x 1024.
  CHECK(light().search_width_texels(10.0) == Approx(921.6).epsilon(1e-12));
}

TEST_CASE("penumbra (Eq. 1): rays from the light's edges past a blocker edge at depth 5 spread to width 2 at depth 10") {
  CHECK(light().penumbra_world(10.0, 5.0) == Approx(2.0).epsilon(1e-12));
  // 2 world units at depth 10 -> 2 x (1 / 10) at the near plane -> 0.2 / 2 x 1024 = 102.4 texels.
  CHECK(light().penumbra_texels(10.0, 5.0) == Approx(102.4).epsilon(1e-12));
}

TEST_CASE("degenerate inputs give 0 texels, never NaN: point light, blocker behind, before the near plane, NaN") {
  pn::LightModel point = light();
  point.width = 0.0;
  CHECK(point.penumbra_texels(10.0, 5.0) == 0.0);
  CHECK(light().penumbra_texels(5.0, 6.0) == 0.0);
  CHECK(light().blocker_window_texels(10.0, 0.5) == 0.0);
  CHECK(light().penumbra_texels(0.5, 0.25) == 0.0);
  CHECK(light().penumbra_texels(std::nan(""), 5.0) == 0.0);
  CHECK(light().blocker_window_texels(std::numeric_limits<double>::infinity(), 2.0) == 0.0);
}

TEST_CASE("negative: a light with a negative or NaN width, near >= far or a bad field of view is refused") {
  pn::LightModel l = light();
  l.width = -1;
  CHECK_THROWS_WITH(l.validate(), "light width -1: expected a finite number >= 0");
  l = light(), l.width = std::nan("");
  CHECK_THROWS_WITH(l.validate(), Catch::Contains("light width nan"));
  l = light(), l.far_plane = 0.5;
  CHECK_THROWS_WITH(l.validate(), Catch::Contains("light far plane 0.5"));
  l = light(), l.fov_radians = 4;
  CHECK_THROWS_WITH(l.validate(), Catch::Contains("light field of view 4"));
  CHECK_NOTHROW(light().validate());
}

TEST_CASE("directional light: the sun's rays spread S = 2 tan(theta / 2) per unit of distance, on an orthographic map") {
  // S = 0.01 (theta ~ 0.573 deg), texels 0.05 wide, depth range from 1.
  pn::LightModel sun{0.0, 1.0, 400.0, 0.0, 1024, 0.01, 0.05};
  REQUIRE_NOTHROW(sun.validate());
  // A receiver at 101 sees the sun's disc through a window 0.01 x 100 = 1 world unit wide at depth 1: 20 texels.
  CHECK(sun.search_width_texels(101.0) == Approx(20.0).epsilon(1e-12));
  // Blockers at 81: the window is 0.01 x 20 = 0.2 wide, 4 texels, whatever the depths themselves.
  CHECK(sun.blocker_window_texels(101.0, 81.0) == Approx(4.0).epsilon(1e-12));
  CHECK(sun.blocker_window_texels(301.0, 281.0) == Approx(4.0).epsilon(1e-12));
  // Eq. 1 at infinity: the penumbra is S (dP - dz), 0.2 world units = 4 texels.
  CHECK(sun.penumbra_world(101.0, 81.0) == Approx(0.2).epsilon(1e-12));
  CHECK(sun.penumbra_texels(101.0, 81.0) == Approx(4.0).epsilon(1e-12));
  CHECK(sun.texel_world_at(5.0) == 0.05);
  // No spread: hard shadows; a perspective light's texel grows with depth: 10 x W_n(2) / (1 x 1024).
  pn::LightModel point_sun = sun;
  point_sun.spread = 0.0;
  CHECK(point_sun.penumbra_texels(101.0, 81.0) == 0.0);
  CHECK(light().texel_world_at(10.0) == Approx(20.0 / 1024).epsilon(1e-12));
  // A negative spread or texel width is refused; an orthographic map needs no field of view.
  pn::LightModel bad = sun;
  bad.spread = -1;
  CHECK_THROWS_WITH(bad.validate(), "light spread -1: expected a finite number >= 0");
  bad = sun, bad.texel_world = std::nan("");
  CHECK_THROWS_WITH(bad.validate(), "light texel width nan: expected a finite number >= 0");
}
