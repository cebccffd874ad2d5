// blur.glsl — separable Gaussian blur of a float image of one to four channels.
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
//   One code path for every channel count: the core functions (…Vec4) blur
//   the four channels of a texel at once, each channel by the same weights
//   and taps (the depth-aware cut and the adaptive radius are decided once
//   per tap, not per channel); the scalar functions are their .r, so a
//   single-channel pass costs what it did (the unused channels' arithmetic
//   is dead code the compiler drops). Moments (vsm.glsl: 2 or 4 channels)
//   are blurred by the same functions.
//   The adaptive radius (option) gives each output pixel p its own radius
//     r(p) = clamp(floor(s(p) * k / 2), 0, radius),
//   s(p) the side in shadow-map texels of p's filter region (Step 5; s < 0 or
//   NaN: lit), k the screen pixels per shadow-map texel: the blur never widens
//   a penumbra by more than half its width, and lit pixels and contact
//   shadows (s < 2/k) get r = 0, their value unchanged. Each 1-D pass uses
//   the radius of its output pixel (a gather); sigma stays the same and the
//   truncated kernel is renormalised.
//
// use:
//   float pnBlur1D(sampler2D src, ivec2 p, ivec2 axis, int radius, float sigma)
//   float pnBlur1DDepthAware(sampler2D src, sampler2D depth, ivec2 p, ivec2 axis,
//                            int radius, float sigma, float depthTolerance)
//   float pnBlur1DAdaptive(sampler2D src, sampler2D filterMap, ivec2 p, ivec2 axis,
//                          int radius, float sigma, float pixelsPerTexel)
//   float pnBlur1DDepthAwareAdaptive(sampler2D src, sampler2D depth, sampler2D filterMap,
//                          ivec2 p, ivec2 axis, int radius, float sigma,
//                          float depthTolerance, float pixelsPerTexel)
//   vec4  pnBlur1DVec4, pnBlur1DDepthAwareVec4, pnBlur1DAdaptiveVec4,
//         pnBlur1DDepthAwareAdaptiveVec4 (same parameters): every channel of src
//   int   pnBlurAdaptiveRadius(float filterSide, float pixelsPerTexel, int radius)
//   float pnBlurGaussian(int offset, float sigma)   unnormalised weight
//   p, axis in texels (axis = ivec2(1,0) or ivec2(0,1)); radius is clamped to
//   [0, PN_BLUR_MAX_RADIUS]; sigma <= 0 or NaN returns the centre texel.
//   depthTolerance is relative: |d_tap - d_centre| <= depthTolerance * |d_centre|.
//   filterMap: the filter-region map, (d, x, y, s) per pixel (pcss_regions.glsl),
//   of the size of src; only .w (s) is read. pixelsPerTexel <= 0 or NaN gives r = 0.
//   Cost: 2r+1 fetches and one exp per pass per texel (4r+2 fetches for
//   depth-aware; the weights by recurrence, pnBlurNextWeight); the adaptive
//   variants add one fetch and cost 2r(p)+1 taps (1 when r(p) = 0).
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

// The weights w_i = exp(-i^2 / (2 sigma^2)) of taps i = 1, 2, ... in turn, by
// recurrence (one exp per pass and pixel instead of 2r): with a = w_1,
//   w_i = w_{i-1} * q_{i-1},  q_i = q_{i-1} * a^2,  w_0 = 1, q_0 = a
// (so q_i = a^(2i+1) and w_i = a^(i^2)); a few float roundings per tap.
struct PnBlurWeights {
  float weight;     // w_i of the last tap
  float ratio;      // q_i = w_{i+1} / w_i
  float ratioStep;  // a^2
};

PnBlurWeights pn_blurWeightsStart(float sigma) {
  float a = pnBlurGaussian(1, sigma);
  return PnBlurWeights(1.0, a, a * a);
}

float pnBlurNextWeight(inout PnBlurWeights g) {
  g.weight *= g.ratio;
  g.ratio *= g.ratioStep;
  return g.weight;
}

bool pn_blurIsFinite(float v) {
  return !isnan(v) && !isinf(v);
}

// Each non-finite channel replaced by PN_BLUR_NONFINITE_VALUE (a select, bit-exact).
vec4 pn_blurSanitize(vec4 v) {
  bvec4 bad = bvec4(ivec4(isnan(v)) | ivec4(isinf(v)));
  return mix(v, vec4(float(PN_BLUR_NONFINITE_VALUE)), bad);
}

// Effective radius: clamped, and 0 when sigma cannot define a Gaussian.
int pn_blurRadius(int radius, float sigma) {
  return (sigma > 0.0) ? clamp(radius, 0, PN_BLUR_MAX_RADIUS) : 0;
}

// Clamp-to-edge fetch; every read stays inside the texture.
vec4 pn_blurFetch4(sampler2D tex, ivec2 p) {
  ivec2 last = textureSize(tex, 0) - ivec2(1);
  return texelFetch(tex, clamp(p, ivec2(0), last), 0);
}

float pn_blurFetch(sampler2D tex, ivec2 p) {
  return pn_blurFetch4(tex, p).r;
}

vec4 pn_blurValue(sampler2D src, ivec2 p) {
  return pn_blurSanitize(pn_blurFetch4(src, p));
}

// The centre (weight 1), then the taps at -i and +i for i = 1..r.
vec4 pnBlur1DVec4(sampler2D src, ivec2 p, ivec2 axis, int radius, float sigma) {
  int r = pn_blurRadius(radius, sigma);
  vec4 sum = pn_blurValue(src, p);
  float weightSum = 1.0;
  PnBlurWeights g = pn_blurWeightsStart(sigma);
  for (int i = 1; i <= r; ++i) {
    float w = pnBlurNextWeight(g);
    sum += w * (pn_blurValue(src, p - i * axis) + pn_blurValue(src, p + i * axis));
    weightSum += 2.0 * w;
  }
  return sum / weightSum;
}

// Two depths belong to the same surface when both are finite and within the
// relative tolerance, or both are non-finite ("no surface", SPEC §3).
bool pn_blurSameSurface(float centreDepth, float tapDepth, float depthTolerance) {
  bool centreFinite = pn_blurIsFinite(centreDepth);
  bool tapFinite = pn_blurIsFinite(tapDepth);
  if (!centreFinite || !tapFinite) return centreFinite == tapFinite;
  return abs(tapDepth - centreDepth) <= depthTolerance * abs(centreDepth);
}

float pnBlur1D(sampler2D src, ivec2 p, ivec2 axis, int radius, float sigma) {
  return pnBlur1DVec4(src, p, axis, radius, sigma).r;
}

// The centre always counts (so weightSum >= 1); a tap at -i or +i only on the centre's surface.
vec4 pnBlur1DDepthAwareVec4(sampler2D src, sampler2D depth, ivec2 p, ivec2 axis, int radius, float sigma,
                            float depthTolerance) {
  int r = pn_blurRadius(radius, sigma);
  float centreDepth = pn_blurFetch(depth, p);
  vec4 sum = pn_blurValue(src, p);
  float weightSum = 1.0;
  PnBlurWeights g = pn_blurWeightsStart(sigma);
  for (int i = 1; i <= r; ++i) {
    float w = pnBlurNextWeight(g);
    for (int side = -1; side <= 1; side += 2) {
      ivec2 q = p + side * i * axis;
      if (!pn_blurSameSurface(centreDepth, pn_blurFetch(depth, q), depthTolerance)) continue;
      sum += w * pn_blurValue(src, q);
      weightSum += w;
    }
  }
  return sum / weightSum;
}

float pnBlur1DDepthAware(sampler2D src, sampler2D depth, ivec2 p, ivec2 axis, int radius, float sigma,
                         float depthTolerance) {
  return pnBlur1DDepthAwareVec4(src, depth, p, axis, radius, sigma, depthTolerance).r;
}

// r(p) from p's filter side s (texels) and k = pixelsPerTexel (screen pixels
// per texel): floor(s k / 2) in float arithmetic, clamped to [0, radius] and
// to [0, PN_BLUR_MAX_RADIUS]. Lit (s < 0), NaN, contact (s k < 2) and k <= 0
// or NaN give 0; s k = +Inf gives the bound.
int pnBlurAdaptiveRadius(float filterSide, float pixelsPerTexel, int radius) {
  float halfWidth = 0.5 * filterSide * pixelsPerTexel;  // half the penumbra, in screen pixels
  int bound = clamp(radius, 0, PN_BLUR_MAX_RADIUS);
  if (!(pixelsPerTexel > 0.0) || !(halfWidth >= 1.0)) return 0;
  return int(min(floor(halfWidth), float(bound)));
}

// The filter side of pixel p (.w of its filter-region entry), clamp-to-edge.
float pn_blurFilterSide(sampler2D filterMap, ivec2 p) {
  ivec2 last = textureSize(filterMap, 0) - ivec2(1);
  return texelFetch(filterMap, clamp(p, ivec2(0), last), 0).w;
}

// The per-pixel-radius passes: pnBlur1D / pnBlur1DDepthAware with the
// output pixel's radius r(p); a pixel of radius 0 is a copy of its texel
// (what the 1-tap pass returns, without the depth fetch and the weight).
vec4 pnBlur1DAdaptiveVec4(sampler2D src, sampler2D filterMap, ivec2 p, ivec2 axis, int radius, float sigma,
                          float pixelsPerTexel) {
  int r = pnBlurAdaptiveRadius(pn_blurFilterSide(filterMap, p), pixelsPerTexel, pn_blurRadius(radius, sigma));
  if (r == 0) return pn_blurValue(src, p);
  return pnBlur1DVec4(src, p, axis, r, sigma);
}

float pnBlur1DAdaptive(sampler2D src, sampler2D filterMap, ivec2 p, ivec2 axis, int radius, float sigma,
                       float pixelsPerTexel) {
  return pnBlur1DAdaptiveVec4(src, filterMap, p, axis, radius, sigma, pixelsPerTexel).r;
}

vec4 pnBlur1DDepthAwareAdaptiveVec4(sampler2D src, sampler2D depth, sampler2D filterMap, ivec2 p, ivec2 axis,
                                    int radius, float sigma, float depthTolerance, float pixelsPerTexel) {
  int r = pnBlurAdaptiveRadius(pn_blurFilterSide(filterMap, p), pixelsPerTexel, pn_blurRadius(radius, sigma));
  if (r == 0) return pn_blurValue(src, p);
  return pnBlur1DDepthAwareVec4(src, depth, p, axis, r, sigma, depthTolerance);
}

float pnBlur1DDepthAwareAdaptive(sampler2D src, sampler2D depth, sampler2D filterMap, ivec2 p, ivec2 axis,
                                 int radius, float sigma, float depthTolerance, float pixelsPerTexel) {
  return pnBlur1DDepthAwareAdaptiveVec4(src, depth, filterMap, p, axis, radius, sigma, depthTolerance,
                                        pixelsPerTexel).r;
}

#endif  // PENUMBRA_BLUR_GLSL
