// CPU reference for glsl/receiver_plane.glsl, from its definition in double:
// the step per axis (the one-sided difference with the smaller |Δd| between
// valid G-buffer entries, the later one on a tie), the gradient g solving
// g · (a.u, a.v) = a.d and g · (b.u, b.v) = b.d (by the inverse of the steps'
// matrix), 0 when |det| <= PN_RECEIVER_PLANE_MIN_SINE |a.uv| |b.uv| or not finite, clamped to
// maxSlope; the plane's range over a rectangle by visiting every texel centre;
// and the shadow test's threshold at a texel: the plane, never behind the receiver.
#pragma once

#include <algorithm>
#include <array>

namespace pn {

using Entry4 = std::array<double, 4>;  // (u, v, d, valid)
using Step3 = std::array<double, 3>;   // (du, dv, dd)

Step3 receiver_plane_step(const Entry4& centre, const Entry4& minus, const Entry4& plus);
std::array<double, 2> receiver_plane_gradient(const Step3& a, const Step3& b, double max_slope);
// (min, max) of d + g · (q + ½ − (u, v)) over the texels q of [origin, origin + size).
std::array<double, 2> receiver_plane_range(const Step3& receiver, const std::array<double, 2>& gradient,
                                           const std::array<int, 2>& origin, const std::array<int, 2>& size);

// The threshold a texel's depth is compared with, its centre `along` = g · (q + ½ − (u, v)) up the
// receiver's plane: t0 + along, but never above t0 (the receiver's depth minus the bias): a blocker
// lies nearer the light than the receiver it shadows, so the plane only lowers the threshold.
inline double receiver_plane_threshold(double t0, double along) { return std::min(t0, t0 + along); }

}  // namespace pn
