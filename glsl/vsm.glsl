// vsm.glsl — variance shadow maps (VSM) and exponential variance shadow maps (EVSM).
//
// description:
//   Seed 003 §3 (Eq. 9–13): a map of moments M1 = E[d], M2 = E[d^2], filtered
//   (blurred) like a texture; per receiver the mean mu = M1 and variance
//   sigma^2 = M2 - M1^2, and the one-sided Chebyshev (Cantelli) inequality
//     P(d >= t) <= p_max(t) = sigma^2 / (sigma^2 + (t - mu)^2)   for t > mu,
//     p_max(t) = 1                                               for t <= mu,
//   t = dP - bias, as the visibility of the receiver (an upper bound of the
//   Gaussian-weighted PCF visibility over the blur's window; exact for a
//   window of one depth plane and one occluder plane).
//   Minimum variance: sigma^2 = max(M2 - M1^2, minVariance * M1^2) — scaled by
//   the squared mean (relative), so it absorbs the float cancellation of
//   M2 - M1^2 (about 2^-23 M1^2) at every depth, and means the same in EVSM's
//   warped units; and at least PN_VSM_VARIANCE_FLOOR (FLT_MIN), so a mean
//   of 0 never gives 0 / 0.
//   Light-bleeding reduction: p -> linstep(a, 1, p) = clamp((p - a) / (1 - a), 0, 1),
//   a in [0, PN_VSM_MAX_BLEEDING_REDUCTION]: the tail of p below a, which
//   in a window of two occluders over a receiver is light that the
//   receiver does not get, is cut to 0 (at the cost of darker penumbrae).
//   Depth-range bound (seed 003 §3.2: the depth map's min and max): over the
//   square of side 2r+1 centred on the receiver's texel (the blur's window,
//   pushed inside the map: a superset of the clamped window, so the bound is
//   conservative), read from depth_pyramid.glsl in 4 fetches,
//     t <= min  -> visibility 1 (no texel occludes: d < t fails for all),
//     t >  max  -> visibility 0 (every texel occludes),
//   otherwise the (reduced) Chebyshev bound. It removes light bleeding and
//   the min-variance darkening where the window is one-sided.
//   EVSM (beyond the seed): the depth normalised by a range (near, far) to
//   x = clamp((d - near) / (far - near), 0, 1) and warped,
//     positive  w+ = exp(c+ x),    moments (w+, w+^2)
//     negative  w- = -exp(-c- x),  moments (w-, w-^2)
//   both increasing in x, so the Chebyshev bound holds for the warped
//   receiver; 2 components use w+, 4 components take the min of both bounds.
//   The warp shrinks the tail that bleeds by exp(-c (t - d)).
//   Non-finite depths (NaN, ±Inf: "no occluder", SPEC §3) enter the moments as
//   the far depth (VSM: farDepth, EVSM: x = 1), never as Inf, so no moment and
//   no bound is NaN. A NaN receiver depth is lit (t > mu is false).
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
//   vec2  pnVsmWindowMinMax(sampler2DArray pyramid, ivec2 texel, int radius)
//   float pnVsmDepthRangeBound(vec2 minMax, float t)                 PN_VSM_BOUND_*
//   float pnEvsmBound2(vec2 moments, float t, vec2 depthRange, float exponent, float minVariance)
//   float pnEvsmBound4(vec4 moments, float t, vec2 depthRange, vec2 exponents, float minVariance)
//   The calls (one receiver, from a lighting shader; 1 where the receiver has no finite
//   position or depth; its texel clamped to the map):
//   float pnVsm(sampler2D moments, sampler2DArray pyramid, vec3 receiver, int radius, float bias,
//               float minVariance, float bleedingReduction)
//   float pnEvsm2(sampler2D moments, sampler2DArray pyramid, vec3 receiver, int radius, float bias,
//                 vec2 depthRange, float exponent, float minVariance, float bleedingReduction)
//   float pnEvsm4(… as pnEvsm2, vec2 exponents …)
//         receiver = (u, v, d) as pnLightProject gives (light_model.glsl); they read the texel under (u, v)
//   Their building blocks, per texel:
//   float pnVsmVisibility(sampler2D moments, sampler2DArray pyramid, ivec2 texel, int radius,
//                         float receiverDepth, float bias, float minVariance, float bleedingReduction)
//   float pnEvsmVisibility2(sampler2D moments, sampler2DArray pyramid, ivec2 texel, int radius,
//                           float receiverDepth, float bias, vec2 depthRange, float exponent,
//                           float minVariance, float bleedingReduction)
//   float pnEvsmVisibility4(… as pnEvsmVisibility2, vec2 exponents …)
//   moments: the blurred moments (blur.glsl's …Vec4 functions over RG32F /
//   RGBA32F), texelFetch at the receiver's texel (clamped into the map);
//   pyramid: depth_pyramid.glsl's pyramid of the same N×N map; radius: the
//   blur's radius, texels. t, depths: linear light depth; bias as everywhere
//   (a texel occludes when d < dP - bias).
//
// options (vsm.h): PN_VSM_MIN_VARIANCE, PN_VSM_BLEEDING_REDUCTION,
//   PN_VSM_MAX_BLEEDING_REDUCTION, PN_EVSM_POSITIVE_EXPONENT,
//   PN_EVSM_NEGATIVE_EXPONENT, PN_EVSM_MAX_EXPONENT (exponents are clamped to
//   it: fp32 overflow, see vsm.h).
//
// cost: moments 1 fetch (and 1 or 2 exp for EVSM) per map texel, then the
//   blur (2·(2r+1) fetches per texel); a receiver: 1 moments fetch, 4 pyramid
//   fetches, a division (two for EVSM-4) — independent of the filter size.
//
// isa budget: vgprs 16, instructions 320, code 2048, scratch 0
//   (`penumbra isa --budgets`: the call as an engine compiles it, RDNA 2 wave64; docs/isa.md)

#ifndef PENUMBRA_VSM_GLSL
#define PENUMBRA_VSM_GLSL

#include "vsm.h"
#include "depth_pyramid.glsl"

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

vec2 pnVsmWindowMinMax(sampler2DArray pyramid, ivec2 texel, int radius) {
  int r = max(radius, 0);
  return pnPyramidSquareMinMax(pyramid, texel - ivec2(r), 2 * r + 1);
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

vec4 pn_vsmFetchMoments(sampler2D moments, ivec2 texel) {
  ivec2 last = textureSize(moments, 0) - ivec2(1);
  return texelFetch(moments, clamp(texel, ivec2(0), last), 0);
}

float pnVsmVisibility(sampler2D moments, sampler2DArray pyramid, ivec2 texel, int radius, float receiverDepth,
                      float bias, float minVariance, float bleedingReduction) {
  float t = receiverDepth - bias;
  float p = pnVsmChebyshev(pn_vsmFetchMoments(moments, texel).xy, t, minVariance);
  float bound = pnVsmDepthRangeBound(pnVsmWindowMinMax(pyramid, texel, radius), t);
  return pn_vsmApplyBound(bound, pnVsmReduceBleeding(p, bleedingReduction));
}

float pnEvsmVisibility2(sampler2D moments, sampler2DArray pyramid, ivec2 texel, int radius, float receiverDepth,
                        float bias, vec2 depthRange, float exponent, float minVariance, float bleedingReduction) {
  float t = receiverDepth - bias;
  float p = pnEvsmBound2(pn_vsmFetchMoments(moments, texel).xy, t, depthRange, exponent, minVariance);
  float bound = pnVsmDepthRangeBound(pnVsmWindowMinMax(pyramid, texel, radius), t);
  return pn_vsmApplyBound(bound, pnVsmReduceBleeding(p, bleedingReduction));
}

float pnEvsmVisibility4(sampler2D moments, sampler2DArray pyramid, ivec2 texel, int radius, float receiverDepth,
                        float bias, vec2 depthRange, vec2 exponents, float minVariance, float bleedingReduction) {
  float t = receiverDepth - bias;
  float p = pnEvsmBound4(pn_vsmFetchMoments(moments, texel), t, depthRange, exponents, minVariance);
  float bound = pnVsmDepthRangeBound(pnVsmWindowMinMax(pyramid, texel, radius), t);
  return pn_vsmApplyBound(bound, pnVsmReduceBleeding(p, bleedingReduction));
}

// The texel under a receiver's (u, v), clamped to the moments' map; false when its position or
// depth is not finite (nothing to test: lit).
bool pn_vsmReceiverTexel(sampler2D moments, vec3 receiver, out ivec2 texel) {
  ivec2 n = textureSize(moments, 0);
  texel = ivec2(clamp(floor(receiver.xy), vec2(0.0), vec2(n - ivec2(1))));
  return pn_vsmIsFinite(receiver.x) && pn_vsmIsFinite(receiver.y) && pn_vsmIsFinite(receiver.z);
}

float pnVsm(sampler2D moments, sampler2DArray pyramid, vec3 receiver, int radius, float bias, float minVariance,
            float bleedingReduction) {
  ivec2 texel;
  if (!pn_vsmReceiverTexel(moments, receiver, texel)) return 1.0;
  return pnVsmVisibility(moments, pyramid, texel, radius, receiver.z, bias, minVariance, bleedingReduction);
}

float pnEvsm2(sampler2D moments, sampler2DArray pyramid, vec3 receiver, int radius, float bias, vec2 depthRange,
              float exponent, float minVariance, float bleedingReduction) {
  ivec2 texel;
  if (!pn_vsmReceiverTexel(moments, receiver, texel)) return 1.0;
  return pnEvsmVisibility2(moments, pyramid, texel, radius, receiver.z, bias, depthRange, exponent, minVariance,
                           bleedingReduction);
}

float pnEvsm4(sampler2D moments, sampler2DArray pyramid, vec3 receiver, int radius, float bias, vec2 depthRange,
              vec2 exponents, float minVariance, float bleedingReduction) {
  ivec2 texel;
  if (!pn_vsmReceiverTexel(moments, receiver, texel)) return 1.0;
  return pnEvsmVisibility4(moments, pyramid, texel, radius, receiver.z, bias, depthRange, exponents, minVariance,
                           bleedingReduction);
}

#endif  // PENUMBRA_VSM_GLSL
