// blur.glsl — separable Gaussian blur of a single-channel float image.
//
// description:
//   One 1-D pass of a normalised Gaussian of radius r and standard deviation
//   sigma (seed 000 §5.3: horizontal pass, then vertical pass, radius 3):
//     out(p) = sum_{i=-r..r} w_i * v(clamp(p + i*axis)) / sum_{i=-r..r} w_i,
//     w_i = exp(-i^2 / (2 sigma^2)).
//   Two passes (axis (1,0) then (0,1)) equal the 2-D Gaussian convolution
//   with clamped edges, because clamping acts on each axis separately.
//   Non-finite texels (NaN, ±Inf) read as PN_BLUR_NONFINITE_VALUE, so a blur
//   never spreads NaN. The depth-aware variant drops taps whose depth is not
//   within a relative tolerance of the centre's (a cross-bilateral cut that
//   keeps penumbrae from bleeding across depth edges) and renormalises.
//
// use:
//   float pnBlur1D(sampler2D src, ivec2 p, ivec2 axis, int radius, float sigma)
//   float pnBlur1DDepthAware(sampler2D src, sampler2D depth, ivec2 p, ivec2 axis,
//                            int radius, float sigma, float depthTolerance)
//   float pnBlurGaussian(int offset, float sigma)   unnormalised weight
//   p, axis in texels (axis = ivec2(1,0) or ivec2(0,1)); radius is clamped to
//   [0, PN_BLUR_MAX_RADIUS]; sigma <= 0 or NaN returns the centre texel.
//   depthTolerance is relative: |d_tap - d_centre| <= depthTolerance * |d_centre|.
//   Cost: 2r+1 fetches and exps per pass per texel (4r+2 for depth-aware).
//
// options:
//   PN_BLUR_RADIUS            default radius for callers (3, seed 000 §5.3)
//   PN_BLUR_SIGMA             default sigma for callers (1.0: 3 sigma = radius)
//   PN_BLUR_MAX_RADIUS        loop bound (16)
//   PN_BLUR_NONFINITE_VALUE   value substituted for NaN/±Inf texels (0.0)
//   (all four in blur.h, shared with the runner)

#ifndef PENUMBRA_BLUR_GLSL
#define PENUMBRA_BLUR_GLSL

#include "blur.h"  // PN_BLUR_RADIUS, PN_BLUR_SIGMA, PN_BLUR_MAX_RADIUS, PN_BLUR_NONFINITE_VALUE

float pnBlurGaussian(int offset, float sigma) {
  float t = float(offset) / sigma;
  return exp(-0.5 * t * t);
}

bool pnBlurIsFinite(float v) {
  return !isnan(v) && !isinf(v);
}

// Effective radius: clamped, and 0 when sigma cannot define a Gaussian.
int pnBlurRadius(int radius, float sigma) {
  return (sigma > 0.0) ? clamp(radius, 0, PN_BLUR_MAX_RADIUS) : 0;
}

// Clamp-to-edge fetch; every read stays inside the texture.
float pnBlurFetch(sampler2D tex, ivec2 p) {
  ivec2 last = textureSize(tex, 0) - ivec2(1);
  return texelFetch(tex, clamp(p, ivec2(0), last), 0).r;
}

float pnBlurValue(sampler2D src, ivec2 p) {
  float v = pnBlurFetch(src, p);
  return pnBlurIsFinite(v) ? v : float(PN_BLUR_NONFINITE_VALUE);
}

float pnBlur1D(sampler2D src, ivec2 p, ivec2 axis, int radius, float sigma) {
  int r = pnBlurRadius(radius, sigma);
  float sum = 0.0;
  float weightSum = 0.0;
  for (int i = -r; i <= r; ++i) {
    float w = (r == 0) ? 1.0 : pnBlurGaussian(i, sigma);
    sum += w * pnBlurValue(src, p + i * axis);
    weightSum += w;
  }
  return sum / weightSum;
}

// Two depths belong to the same surface when both are finite and within the
// relative tolerance, or both are non-finite ("no surface", SPEC §3).
bool pnBlurSameSurface(float centreDepth, float tapDepth, float depthTolerance) {
  bool centreFinite = pnBlurIsFinite(centreDepth);
  bool tapFinite = pnBlurIsFinite(tapDepth);
  if (!centreFinite || !tapFinite) return centreFinite == tapFinite;
  return abs(tapDepth - centreDepth) <= depthTolerance * abs(centreDepth);
}

float pnBlur1DDepthAware(sampler2D src, sampler2D depth, ivec2 p, ivec2 axis, int radius, float sigma,
                         float depthTolerance) {
  int r = pnBlurRadius(radius, sigma);
  float centreDepth = pnBlurFetch(depth, p);
  float sum = 0.0;
  float weightSum = 0.0;
  for (int i = -r; i <= r; ++i) {
    ivec2 q = p + i * axis;
    // The centre tap always counts, so weightSum > 0.
    if (i != 0 && !pnBlurSameSurface(centreDepth, pnBlurFetch(depth, q), depthTolerance)) continue;
    float w = (r == 0) ? 1.0 : pnBlurGaussian(i, sigma);
    sum += w * pnBlurValue(src, q);
    weightSum += w;
  }
  return sum / weightSum;
}

#endif  // PENUMBRA_BLUR_GLSL
