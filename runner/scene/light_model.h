// The light (an area light with a perspective map, or a directional light with an
// orthographic one) and its widths in shadow-map texels, on the CPU: the same
// formulas as glsl/light_model.glsl (SPEC §4.7), the one C++ place they live.
#pragma once

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/format.h"

namespace pn {

struct LightModel {
  double width = 1.0;         // w_L, world units (area light; 0 for a directional light)
  double near_plane = 1.0;    // n (orthographic: the depth range's start)
  double far_plane = 100.0;   // f
  double fov_radians = 1.0;   // full field of view of the square shadow map (perspective)
  int map_size = 1024;        // N
  double spread = 0.0;        // S = 2 tan(theta / 2): a directional light's width per unit of distance
  double texel_world = 0.0;   // t > 0: an orthographic map (a cascade) with texels t wide; 0: perspective

  bool orthographic() const { return texel_world > 0; }
  double near_plane_width() const { return 2.0 * near_plane * std::tan(0.5 * fov_radians); }  // W_n

  // Throws Error naming the parameter unless the light is usable: width and spread finite
  // and >= 0 (both 0: a point light, hard shadows), 0 < near < far, N >= 2, and
  // 0 < fov < pi (perspective) or t finite (orthographic).
  void validate() const {
    const auto bad = [](const char* what, double v, const char* expected) {
      return Error(std::string("light ") + what + " " + format_number("%g", v) + ": expected " + expected);
    };
    if (!std::isfinite(width) || width < 0) throw bad("width", width, "a finite number >= 0");
    if (!std::isfinite(spread) || spread < 0) throw bad("spread", spread, "a finite number >= 0");
    if (!std::isfinite(near_plane) || near_plane <= 0) throw bad("near plane", near_plane, "a finite number > 0");
    if (!std::isfinite(far_plane) || far_plane <= near_plane) throw bad("far plane", far_plane, "a finite number > near");
    if (!std::isfinite(texel_world) || texel_world < 0) throw bad("texel width", texel_world, "a finite number >= 0");
    if (!orthographic() && (!(fov_radians > 0) || !(fov_radians < 3.14159265358979)))
      throw bad("field of view", fov_radians, "0 < fov < pi radians");
    if (map_size < 2) throw bad("shadow map size", map_size, "N >= 2");
  }

  static double positive_or_zero(double x) { return (x > 0 && std::isfinite(x)) ? x : 0.0; }

  // A texel's world width at light depth d: t, or d W_n / (n N).
  double texel_world_at(double depth) const {
    return orthographic() ? texel_world : positive_or_zero(depth * near_plane_width() / (near_plane * map_size));
  }

  // Window of blockers at depth z that can shadow a receiver at dP, in texels:
  // (dP − z)(w_L / dP + S) world units at z.
  double blocker_window_texels(double receiver, double blocker) const {
    if (!(receiver > blocker) || !(blocker >= near_plane)) return 0.0;
    const double texel = texel_world_at(blocker);
    if (!(texel > 0)) return 0.0;
    return positive_or_zero((receiver - blocker) * (width / receiver + spread) / texel);
  }
  double search_width_texels(double receiver) const { return blocker_window_texels(receiver, near_plane); }

  // Eq. (1): s_p = (dP − dz)(w_L / dz + S), world units at the receiver (w_L (dP − dz) / dz for the
  // area light, S (dP − dz) for the sun), and in texels.
  double penumbra_world(double receiver, double blocker) const {
    if (!(receiver > blocker) || !(blocker > 0)) return 0.0;
    return positive_or_zero((receiver - blocker) * (width / blocker + spread));
  }
  double penumbra_texels(double receiver, double blocker) const {
    if (!(receiver >= near_plane)) return 0.0;
    const double texel = texel_world_at(receiver);
    if (!(texel > 0)) return 0.0;
    return positive_or_zero(penumbra_world(receiver, blocker) / texel);
  }
};

}  // namespace pn
