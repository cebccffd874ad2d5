// CPU references for glsl/vsm.glsl, written from the definitions, not from the
// shader: the moments of a depth in double (rounded to float once, as stored);
// the moments over a window as the direct 2-D Gaussian sum of the blur's
// definition (blur_reference on the moment image); Chebyshev's one-sided bound
// in double; the window's min and max by a brute-force scan of the square; the
// exact Gaussian-weighted PCF visibility over the same window by brute force.
#pragma once

#include <array>

#include "core/image.h"
#include "modules/vsm_face.h"
#include "reference/blur_reference.h"

namespace pn {

// The moments of one depth, in double: VSM (d, d^2) with non-finite d read as far;
// EVSM (w+, w+^2[, w-, w-^2]) of x = clamp((d - near) / (far - near), 0, 1) (1 for a
// non-finite d), w+ = exp(c+ x), w- = -exp(-c- x), exponents clamped to [0, kEvsmMaxExponent].
std::array<double, 4> vsm_moments(float depth, const VsmParams& params);
double evsm_warp_coordinate(double depth, const VsmParams& params);

// Every texel's moments rounded to float: vsm_moment_channels(kind) channels.
Image vsm_moments_reference(const Image& depth, const VsmParams& params);

// The direct 2-D Gaussian sum of the moments over each texel's window (params.blur, edges clamped).
Image vsm_window_moments_reference(const Image& depth, const VsmParams& params);

// p_max(t) = s2 / (s2 + (t - mu)^2) for t > mu, else 1 (NaN t: 1); s2 = max(m2 - m1^2, mv m1^2, FLT_MIN).
double chebyshev_bound(double m1, double m2, double t, double min_variance);
// The same from a mean and a variance; and the variance it uses, max(variance, mv mu^2, FLT_MIN).
double chebyshev_bound_variance(double mean, double variance, double t, double min_variance);
double floored_variance(double mean, double variance, double min_variance);
// linstep(a, 1, p), a clamped to [0, kVsmMaxBleedingReduction].
double reduce_bleeding(double p, double amount);
// The kind's bound at t = dP - bias (the float t the module forms) from a texel's window moments
// (2 or 4): VSM Chebyshev; EVSM Chebyshev of the warped t, the min of both for 4 components.
double vsm_bound(const std::array<double, 4>& moments, float t, const VsmParams& params);

// Min and max over the square of side 2r + 1 centred on (x, y), pushed inside the map (side
// clamped to the map); non-finite texels read as +Inf (no occluder).
struct DepthRange {
  float min = 0.0f, max = 0.0f;
};
DepthRange window_depth_range(const Image& depth, int x, int y, int radius);
// PN_VSM_BOUND_LIT (t <= min), _SHADOWED (t > max), else _NONE.
double depth_range_bound(const DepthRange& range, float t);
// The module's visibility: the bound where it decides, else the reduced Chebyshev bound.
double vsm_visibility(double bound_code, double reduced);

// The exact PCF visibility over the blur's window: the Gaussian-weighted fraction of the
// window's texels (edges clamped, the blur's weights) with d >= t — non-finite never occludes.
double gaussian_pcf_visibility(const Image& depth, int x, int y, float t, const BlurParams& blur);

}  // namespace pn
