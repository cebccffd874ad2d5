// The area light and its widths in shadow-map texels, on the CPU: the same
// formulas as glsl/light_model.glsl (SPEC §4.7), the one C++ place they live.
#pragma once

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/format.h"

namespace pn {

struct LightModel {
  double width = 1.0;         // w_L, world units
  double near_plane = 1.0;    // n
  double far_plane = 100.0;   // f
  double fov_radians = 1.0;   // full field of view of the square shadow map
  int map_size = 1024;        // N

  double near_plane_width() const { return 2.0 * near_plane * std::tan(0.5 * fov_radians); }  // W_n

  // Throws Error naming the parameter unless the light is usable: width finite
  // and >= 0 (0: a point light, hard shadows), 0 < near < far, 0 < fov < pi, N >= 2.
  void validate() const {
    const auto bad = [](const char* what, double v, const char* expected) {
      return Error(std::string("light ") + what + " " + format_number("%g", v) + ": expected " + expected);
    };
    if (!std::isfinite(width) || width < 0) throw bad("width", width, "a finite number >= 0");
    if (!std::isfinite(near_plane) || near_plane <= 0) throw bad("near plane", near_plane, "a finite number > 0");
    if (!std::isfinite(far_plane) || far_plane <= near_plane) throw bad("far plane", far_plane, "a finite number > near");
    if (!(fov_radians > 0) || !(fov_radians < 3.14159265358979)) throw bad("field of view", fov_radians, "0 < fov < pi radians");
    if (map_size < 2) throw bad("shadow map size", map_size, "N >= 2");
  }

  static double positive_or_zero(double x) { return (x > 0 && std::isfinite(x)) ? x : 0.0; }

  // Window of blockers at depth z that can shadow a receiver at dP, in texels.
  double blocker_window_texels(double receiver, double blocker) const {
    if (!(receiver > blocker) || !(blocker >= near_plane)) return 0.0;
    const double world = width * (receiver - blocker) / receiver;
    return positive_or_zero(world * (near_plane / blocker) / near_plane_width() * map_size);
  }
  double search_width_texels(double receiver) const { return blocker_window_texels(receiver, near_plane); }

  // Eq. (1): s_p = w_L (dP − dz) / dz, world units at the receiver, and in texels.
  double penumbra_world(double receiver, double blocker) const {
    if (!(receiver > blocker) || !(blocker > 0)) return 0.0;
    return positive_or_zero(width * (receiver - blocker) / blocker);
  }
  double penumbra_texels(double receiver, double blocker) const {
    if (!(receiver >= near_plane)) return 0.0;
    return positive_or_zero(penumbra_world(receiver, blocker) * (near_plane / receiver) / near_plane_width() * map_size);
  }
};

}  // namespace pn
