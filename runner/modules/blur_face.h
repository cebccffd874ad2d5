// C++ face of glsl/blur.glsl: the blur's parameters, its limits and its
// kernel's weights, shared by the blur pass, the pipeline, the metrics and the
// blur's reference.
#pragma once

#include <vector>

#include <blur.h>  // glsl/blur.h: PN_BLUR_*, shared with the shader

namespace pn {

// The shader's limits (glsl/blur.h), which the reference applies too.
inline constexpr int kBlurMaxRadius = PN_BLUR_MAX_RADIUS;
inline constexpr float kBlurNonfiniteValue = static_cast<float>(PN_BLUR_NONFINITE_VALUE);

struct BlurParams {
  int radius = PN_BLUR_RADIUS;   // seed 000 §5.3
  double sigma = PN_BLUR_SIGMA;  // 3 sigma = radius
  bool depth_aware = false;
  double depth_tolerance = 0.05;  // relative, depth-aware only
  bool adaptive = false;          // per-pixel radius from the filter-region map (blur_adaptive_radius)
  float pixels_per_texel = 1.0f;  // k: screen pixels per shadow-map texel, adaptive only

  // Throws Error naming the parameter and the accepted range.
  void validate() const;
};

// exp(-i^2 / (2 sigma^2)): the unnormalised weight of the tap i texels away.
double gaussian_weight(int offset, double sigma);

// gaussian_weight(i) / sum over i in [-r, r]; index i + r.
std::vector<double> normalised_gaussian(int radius, double sigma);

}  // namespace pn
