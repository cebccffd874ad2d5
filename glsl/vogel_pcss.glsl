// vogel_pcss.glsl — PCSS with a Vogel (golden-angle) disk of samples rotated
// per pixel by interleaved gradient noise: the one-pass soft shadow three.js,
// Godot and bgfx ship, 12–32 taps, no disk table to upload.
//
// description:
//   A disk of diameter s (texels) around the centre c (texels, continuous:
//   texel (i, j) covers [i, i+1) × [j, j+1)), `count` = n samples and a turn
//   τ (a rotation in turns, [0, 1)). Sample k < n lies at
//     p_k = c + (s / 2) · ρ_k (cos θ_k, sin θ_k),
//     ρ_k = sqrt((k + 1/2) / n),   θ_k = 2π (fract(k g + τ) - 1/2),
//   g = (3 - √5) / 2 the golden angle in turns (θ in [-π, π): the argument
//   range in which GPUs' sin and cos are accurate). The n points cover the
//   disk with even density, each new one in the largest gap the previous left
//   (Vogel's spiral), so any n is a good disk and no table is needed.
//   Each sample reads the texel it falls in, floor(p_k); with t = dP - bias
//     occluders = #{ k : p_k inside the map, d(floor(p_k)) < t },
//     depthSum = sum of those d,  samples = n (those outside the map included)
//   (with a receiver plane of gradient g the texel q compares with
//   t + g · (q + 1/2 - c): receiver_plane.glsl)
//   — PnPoisson's sums, accumulated by poisson_pcss.glsl's pnPoissonAddSamplePlane,
//   so the two disks agree on every rule: a sample outside the map or at a
//   non-finite position occludes nothing, non-finite texels never occlude.
//   The per-pixel turn is interleaved gradient noise (Jimenez 2014) at the
//   pixel's centre q = pixel + 1/2 (gl_FragCoord.xy):
//     τ = fract(52.9829189 · fract(0.06711056 q.x + 0.00583715 q.y)),
//   which spreads neighbouring pixels' rotations evenly, so that the noise of
//   a small disk is high-frequency (a TAA or a small blur removes it).
//
// The call (PCSS as engines ship it, in one pass): PCSS's search width for
//   the receiver's depth (light_model.glsl), the blocker search with a Vogel
//   disk of blockerSamples over it — no blocker: lit, 1 at once —, the
//   penumbra of Eq. (1) from the blocker mean times filterScale as the
//   filter disk's diameter (pnFilterEntry, pcss_regions.glsl), and PCF with a
//   Vogel disk of filterSamples over it: visibility = 1 - occluded fraction.
//   Both disks use the pixel's turn.
//
// use:
//   float pnVogelPcss(sampler2D depthMap, PnLight light, vec3 receiver, ivec2 pixel, PnVogelPcssSettings settings)
//         receiver = (u, v, d) as pnLightProject gives; pixel = the screen pixel
//         (ivec2(gl_FragCoord.xy) or gl_GlobalInvocationID.xy), which seeds the rotation
//   float pnVogelPcss(sampler2D depthMap, PnLight light, vec3 receiver, vec2 receiverPlane, ivec2 pixel,
//                     PnVogelPcssSettings settings)
//         with the receiver-plane depth bias (receiver_plane.glsl): receiverPlane = the light depth's
//         gradient across the map, e.g. pnReceiverPlaneGradient(dFdx(receiver), dFdy(receiver), maxSlope);
//         vec2(0.0) is the call above
//   PnVogelPcssSettings pnVogelPcssDefaults(float bias)   16 / 32 samples, filterScale 1
//   PnVogelPcssResult pnVogelPcssEstimate(depthMap, light, receiver, receiverPlane, pixel, settings)
//         visibility, the regions, the mean, the turn
//   PnPoisson pnVogelOcclusion(sampler2D depthMap, vec2 centre, float diameter, float receiverDepth,
//                              float bias, int count, float turn, vec2 gradient)   one disk (count
//                              clamped to [0, PN_VOGEL_MAX_SAMPLES]); gradient: the receiver plane's
//                              (texel q's threshold + gradient · (q + 1/2 - centre)), or vec2(0.0)
//   vec2  pnVogelOffset(int k, int count, float turn)   sample k in the unit disk
//   float pnInterleavedGradientNoise(vec2 position)     in [0, 1); position = gl_FragCoord.xy
//   depthMap: linear light depth in .r (R32F or any float format), texelFetch only.
//
// options:
//   PN_VOGEL_MAX_SAMPLES       the loops' bound and the largest count (128; vogel_pcss.h)
//   PN_VOGEL_BLOCKER_SAMPLES, PN_VOGEL_PCF_SAMPLES   the defaults (16, 32; vogel_pcss.h)
//
// cost: per sample one texelFetch, a sqrt, a sin and a cos and ~12 ALU
//   operations; blockerSamples + filterSamples fetches per shadowed receiver,
//   blockerSamples per lit one, whatever the penumbra's width.
//
// isa budget: vgprs 16, instructions 900, code 5120, scratch 0, loop 90, loops 90
//   (`penumbra isa --budgets`: the call as an engine compiles it, RDNA 2 wave64; docs/isa.md)

#ifndef PENUMBRA_VOGEL_PCSS_GLSL
#define PENUMBRA_VOGEL_PCSS_GLSL

#include "light_model.glsl"
#include "pcss_regions.glsl"
#include "poisson_pcss.glsl"
#include "vogel_pcss.h"

float pnInterleavedGradientNoise(vec2 position) {
  return fract(PN_IGN_Z * fract(dot(position, vec2(PN_IGN_X, PN_IGN_Y))));
}

vec2 pnVogelOffset(int k, int count, float turn) {
  float rho = sqrt((float(k) + 0.5) / float(count));
  float theta = 6.283185307179586 * (fract(float(k) * PN_VOGEL_GOLDEN_TURN + turn) - 0.5);
  return rho * vec2(cos(theta), sin(theta));
}

PnPoisson pnVogelOcclusion(sampler2D depthMap, vec2 centre, float diameter, float receiverDepth, float bias,
                           int count, float turn, vec2 gradient) {
  PnPoisson sums = PnPoisson(0.0, 0.0, 0.0);
  float radius = 0.5 * diameter;
  float t = receiverDepth - bias;
  int n = clamp(count, 0, PN_VOGEL_MAX_SAMPLES);
  for (int k = 0; k < PN_VOGEL_MAX_SAMPLES; ++k) {
    if (k >= n) break;
    sums = pnPoissonAddSamplePlane(depthMap, centre, radius, pnVogelOffset(k, n, turn), vec2(1.0, 0.0), t, gradient,
                                   sums);
  }
  return sums;
}

struct PnVogelPcssSettings {
  float bias;          // light-depth units: a sample occludes when its depth < d - bias
  float filterScale;   // c: filter diameter = c · penumbra
  int blockerSamples;  // 1..PN_VOGEL_MAX_SAMPLES (clamped)
  int filterSamples;
};

struct PnVogelPcssResult {
  float visibility;   // 1 - occluded fraction; 1 when lit
  vec4 searchEntry;   // (d, x, y, s): s the search disk's diameter; s < 0: no surface
  vec4 filterEntry;   // s the filter disk's; s < 0: lit (no blocker)
  float blockerMean;  // 0 without a blocker
  float turn;         // the pixel's rotation, in turns
};

PnVogelPcssSettings pnVogelPcssDefaults(float bias) {
  return PnVogelPcssSettings(bias, 1.0, PN_VOGEL_BLOCKER_SAMPLES, PN_VOGEL_PCF_SAMPLES);
}

PnVogelPcssResult pnVogelPcssEstimate(sampler2D depthMap, PnLight light, vec3 receiver, vec2 receiverPlane,
                                      ivec2 pixel, PnVogelPcssSettings s) {
  float turn = pnInterleavedGradientNoise(vec2(pixel) + 0.5);
  PnVogelPcssResult r = PnVogelPcssResult(1.0, pn_searchStart(light, vec4(receiver, 1.0)), vec4(0.0), 0.0, turn);
  r.filterEntry = vec4(r.searchEntry.xyz, PN_REGION_LIT);
  if (pnEntryLit(r.searchEntry)) return r;
  PnPoisson blockers = pnVogelOcclusion(depthMap, r.searchEntry.yz, r.searchEntry.w, r.searchEntry.x, s.bias,
                                        s.blockerSamples, turn, receiverPlane);
  bool hasBlocker = blockers.occluders > 0.0;
  r.blockerMean = pnPoissonBlockerMean(blockers);
  r.filterEntry = pnFilterEntry(light, r.searchEntry, r.blockerMean, hasBlocker, s.filterScale);
  if (pnEntryLit(r.filterEntry)) return r;  // no blocker: lit, no PCF
  PnPoisson filtered = pnVogelOcclusion(depthMap, r.filterEntry.yz, r.filterEntry.w, r.filterEntry.x, s.bias,
                                        s.filterSamples, turn, receiverPlane);
  r.visibility = 1.0 - pnPoissonOccludedFraction(filtered);
  return r;
}

float pnVogelPcss(sampler2D depthMap, PnLight light, vec3 receiver, vec2 receiverPlane, ivec2 pixel,
                  PnVogelPcssSettings settings) {
  return pnVogelPcssEstimate(depthMap, light, receiver, receiverPlane, pixel, settings).visibility;
}

float pnVogelPcss(sampler2D depthMap, PnLight light, vec3 receiver, ivec2 pixel, PnVogelPcssSettings settings) {
  return pnVogelPcss(depthMap, light, receiver, vec2(0.0), pixel, settings);
}

#endif  // PENUMBRA_VOGEL_PCSS_GLSL
