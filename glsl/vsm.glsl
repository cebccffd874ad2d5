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
//   (the moments, Chebyshev's bound, the bleeding reduction and the depth-range bound:
//   variance_bound.glsl, which this file includes)
//   vec2  pnVsmWindowMinMax(sampler2DArray pyramid, ivec2 texel, int radius)
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
// isa budget: vgprs 16, instructions 320, code 2048, scratch 0, loop 40, loops 45
//   (`penumbra isa --budgets`: the call as an engine compiles it, RDNA 2 wave64; docs/isa.md)

#ifndef PENUMBRA_VSM_GLSL
#define PENUMBRA_VSM_GLSL

#include "depth_pyramid.glsl"
#include "variance_bound.glsl"  // and vsm.h

vec2 pnVsmWindowMinMax(sampler2DArray pyramid, ivec2 texel, int radius) {
  int r = max(radius, 0);
  return pnPyramidSquareMinMax(pyramid, texel - ivec2(r), 2 * r + 1);
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
