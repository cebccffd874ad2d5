// variance_bound.glsl — the arithmetic variance shadow maps share: moments,
// EVSM's warps, Chebyshev's bound, the light-bleeding reduction and the
// depth-range bound, without a texture (vsm.glsl's calls, savsm.glsl's tables).
//
// description:
//   vsm.glsl's header derives each: the one-sided Chebyshev (Cantelli) bound
//   p_max(t) = sigma^2 / (sigma^2 + (t - mu)^2) for t > mu (1 for t <= mu),
//   the minimum variance max(M2 - M1^2, minVariance · M1^2, FLT_MIN), the
//   reduction linstep(a, 1, p), the depth-range bound (t <= min: 1; t > max:
//   0) and EVSM's warps w+ = exp(c+ x), w- = -exp(-c- x) of the normalised
//   depth x. A file of its own so that a call that reads its moments from
//   elsewhere (savsm.glsl's summed-area tables) includes no pyramid.
//
// use:
//   vec2  pnVsmMoments(float depth, float farDepth)                 (d, d*d)
//   float pnEvsmWarpCoordinate(float depth, vec2 depthRange)        x in [0, 1]
//   vec2  pnEvsmMoments2(float depth, vec2 depthRange, float exponent)
//   vec4  pnEvsmMoments4(float depth, vec2 depthRange, vec2 exponents)   (c+, c-)
//   float pnVsmChebyshev(vec2 moments, float t, float minVariance)   p_max
//   float pnVsmChebyshevMeanVariance(float mu, float variance, float t, float minVariance)
//         the same from a mean and a variance computed elsewhere (savsm.glsl's tables)
//   float pnVsmFlooredVariance(float mu, float variance, float minVariance)   the variance the bound uses
//   float pnVsmReduceBleeding(float p, float amount)                 linstep(a, 1, p)
//   float pnVsmDepthRangeBound(vec2 minMax, float t)                 PN_VSM_BOUND_*
//   float pnEvsmBound2(vec2 moments, float t, vec2 depthRange, float exponent, float minVariance)
//   float pnEvsmBound4(vec4 moments, float t, vec2 depthRange, vec2 exponents, float minVariance)
//
// options (vsm.h): PN_VSM_MIN_VARIANCE, PN_VSM_BLEEDING_REDUCTION,
//   PN_VSM_MAX_BLEEDING_REDUCTION, PN_EVSM_POSITIVE_EXPONENT,
//   PN_EVSM_NEGATIVE_EXPONENT, PN_EVSM_MAX_EXPONENT.
//
// cost: ALU only: a division (two for EVSM-4), 1 or 2 exp for a warp.

#ifndef PENUMBRA_VARIANCE_BOUND_GLSL
#define PENUMBRA_VARIANCE_BOUND_GLSL

#include "vsm.h"

bool pn_vsmIsFinite(float d) {
  return !isnan(d) && !isinf(d);
}

vec2 pnVsmMoments(float depth, float farDepth) {
  float d = pn_vsmIsFinite(depth) ? depth : farDepth;
  return vec2(d, d * d);
}

float pnEvsmWarpCoordinate(float depth, vec2 depthRange) {
  if (!pn_vsmIsFinite(depth)) return 1.0;
  return clamp((depth - depthRange.x) / (depthRange.y - depthRange.x), 0.0, 1.0);
}

vec2 pn_evsmClampExponents(vec2 exponents) {
  return clamp(exponents, vec2(0.0), vec2(float(PN_EVSM_MAX_EXPONENT)));
}

// w+ = exp(c+ x), w- = -exp(-c- x): the warped depths of the coordinate x.
vec2 pn_evsmWarp(float x, vec2 exponents) {
  vec2 c = pn_evsmClampExponents(exponents);
  return vec2(exp(c.x * x), -exp(-c.y * x));
}

vec2 pnEvsmMoments2(float depth, vec2 depthRange, float exponent) {
  float w = pn_evsmWarp(pnEvsmWarpCoordinate(depth, depthRange), vec2(exponent, 0.0)).x;
  return vec2(w, w * w);
}

vec4 pnEvsmMoments4(float depth, vec2 depthRange, vec2 exponents) {
  vec2 w = pn_evsmWarp(pnEvsmWarpCoordinate(depth, depthRange), exponents);
  return vec4(w.x, w.x * w.x, w.y, w.y * w.y);
}

float pnVsmFlooredVariance(float mu, float variance, float minVariance) {
  float varianceFloor = max(max(minVariance, 0.0) * (mu * mu), float(PN_VSM_VARIANCE_FLOOR));
  return max(variance, varianceFloor);
}

float pnVsmChebyshevMeanVariance(float mu, float variance, float t, float minVariance) {
  if (!(t > mu)) return 1.0;  // t <= mu, or NaN
  float v = pnVsmFlooredVariance(mu, variance, minVariance);
  float delta = t - mu;
  return v / (v + delta * delta);
}

float pnVsmChebyshev(vec2 moments, float t, float minVariance) {
  return pnVsmChebyshevMeanVariance(moments.x, moments.y - moments.x * moments.x, t, minVariance);
}

float pnVsmReduceBleeding(float p, float amount) {
  float a = clamp(amount, 0.0, float(PN_VSM_MAX_BLEEDING_REDUCTION));
  return clamp((p - a) / (1.0 - a), 0.0, 1.0);
}

float pnVsmDepthRangeBound(vec2 minMax, float t) {
  if (t <= minMax.x) return PN_VSM_BOUND_LIT;
  if (t > minMax.y) return PN_VSM_BOUND_SHADOWED;
  return PN_VSM_BOUND_NONE;
}

// The bound where it decides, else the visibility.
float pn_vsmApplyBound(float bound, float visibility) {
  return bound == PN_VSM_BOUND_NONE ? visibility : bound;
}

float pnEvsmBound2(vec2 moments, float t, vec2 depthRange, float exponent, float minVariance) {
  if (isnan(t)) return 1.0;  // as pnVsmChebyshev: a NaN receiver is lit
  float w = pn_evsmWarp(pnEvsmWarpCoordinate(t, depthRange), vec2(exponent, 0.0)).x;
  return pnVsmChebyshev(moments, w, minVariance);
}

float pnEvsmBound4(vec4 moments, float t, vec2 depthRange, vec2 exponents, float minVariance) {
  if (isnan(t)) return 1.0;
  vec2 w = pn_evsmWarp(pnEvsmWarpCoordinate(t, depthRange), exponents);
  return min(pnVsmChebyshev(moments.xy, w.x, minVariance), pnVsmChebyshev(moments.zw, w.y, minVariance));
}

#endif  // PENUMBRA_VARIANCE_BOUND_GLSL
