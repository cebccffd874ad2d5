// CPU references for glsl/blur.glsl, written from the definition, not from
// the shader: the plain blur is the direct 2-D convolution with the product
// kernel w_i w_j (never separated); the depth-aware blur is defined as two 1-D
// passes and is computed that way, each tap by its own rule.
#pragma once

#include <vector>

#include "blur.h"  // glsl/blur.h: PN_BLUR_*, shared with the shader
#include "core/image.h"

namespace pn {

// The shader's limits (glsl/blur.h), which the reference applies too.
inline constexpr int kBlurMaxRadius = PN_BLUR_MAX_RADIUS;
inline constexpr float kBlurNonfiniteValue = static_cast<float>(PN_BLUR_NONFINITE_VALUE);

struct BlurParams {
  int radius = PN_BLUR_RADIUS;   // seed 000 §5.3
  double sigma = PN_BLUR_SIGMA;  // 3 sigma = radius
  bool depth_aware = false;
  double depth_tolerance = 0.05;  // relative, depth-aware only

  // Throws Error naming the parameter and the accepted range.
  void validate() const;
};

// exp(-i^2 / (2 sigma^2)): the unnormalised weight of the tap i texels away.
double gaussian_weight(int offset, double sigma);

// gaussian_weight(i) / sum over i in [-r, r]; index i + r.
std::vector<double> normalised_gaussian(int radius, double sigma);

Image blur_reference(const Image& source, const BlurParams& params);
Image blur_depth_aware_reference(const Image& source, const Image& depth, const BlurParams& params);

}  // namespace pn
