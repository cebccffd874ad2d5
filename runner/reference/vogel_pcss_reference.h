// CPU reference for glsl/vogel_pcss.glsl, written from its definition in
// double: sample k of n in a disk of diameter s around centre c, turn τ, lies at
//   p_k = c + (s / 2) ρ_k (cos θ_k, sin θ_k),  ρ_k = sqrt((k + 1/2) / n),
//   θ_k = 2π (fract(k g + τ) − 1/2),  g = (3 − √5) / 2,
// reads texel q = floor(p_k) when p_k is inside the map (nothing otherwise) and
// occludes when that texel's depth d is finite and d < dP − bias + g · (q + ½ − c)
// (g: the receiver plane's gradient, 0 without one). The raw map
// is read (NaN and ±Inf allowed). The per-pixel turn is interleaved gradient
// noise, fract(z · fract(x·q.x + y·q.y)) at the pixel's centre q.
//
// A GPU computes positions in float with sin and cos accurate to an absolute
// error (not correctly rounded), so the reference gives each sample every
// verdict a position within `position_error` texels (per axis) of p_k could
// read: the sums are intervals, tight wherever the texels around a sample agree.
#pragma once

#include <functional>

#include "core/image.h"

namespace pn {

struct VogelPcssQuery {
  double centre_x = 0.0, centre_y = 0.0;  // texels, continuous
  double diameter = 0.0;                  // texels
  double receiver_depth = 0.0, bias = 0.0;
  int count = 0;                          // clamped to [0, kVogelMaxSamples]
  double turn = 0.0;                      // rotation, in turns
  double gradient_x = 0.0, gradient_y = 0.0;  // receiver plane: texel q compares with t + g · (q + 1/2 - c)
};

struct VogelPcssPosition {
  double x = 0.0, y = 0.0;  // texels
};

// Sample k of the clamped count n (0 <= k < n).
VogelPcssPosition vogel_pcss_position(const VogelPcssQuery& query, int k, int n);

struct VogelPcssBounds {
  long occluders_lo = 0, occluders_hi = 0;
  double depth_sum_lo = 0.0, depth_sum_hi = 0.0;
  long samples = 0;    // exact: every sample taken, those outside the map included
  long ambiguous = 0;  // samples whose verdict or depth the position error leaves open
};

// `position_error(k, n)`: texels, per axis, a GPU's position of sample k may be off by; `tie`: the
// fraction of |t| + |g.x Δx| + |g.y Δy| (the threshold's terms at a texel) within which a texel's
// comparison with its threshold may go either way (0: exact).
VogelPcssBounds vogel_pcss_bounds(const Image& depth, const VogelPcssQuery& query,
                                  const std::function<double(int k, int n)>& position_error, double tie);

double interleaved_gradient_noise(double x, double y);  // in [0, 1); (x, y) the pixel's centre

}  // namespace pn
