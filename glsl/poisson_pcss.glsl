// poisson_pcss.glsl — blocker search and percentage-closer filtering with a
// Poisson disk of samples, as engines ship PCSS (seeds 002 / 004).
//
// description:
//   SPEC §4.8 ("Poisson PCSS"). A disk of diameter s (texels) around the
//   centre c = (x, y) (texels, continuous: texel (i, j) covers [i, i+1) ×
//   [j, j+1)), and offsets o_k in the unit disk (k < count). Sample k lies at
//     p_k = c + (s / 2) · R o_k,   R = [r.x  -r.y; r.y  r.x]
//   (r = (cos θ, sin θ) a per-pixel rotation; r = (1, 0) is none) and reads
//   the texel it falls in, floor(p_k). Then, with t = dP - bias,
//     occluders = #{ k : p_k inside the map, d(floor(p_k)) < t }
//     depthSum  = sum of those d
//     samples   = count (every sample, those outside the map included)
//   blocker mean = depthSum / occluders (PCSS's blocker search), occluded
//   fraction = occluders / samples (PCF; visibility = 1 - fraction).
//   A sample outside the map occludes nothing (nor does one at a non-finite
//   position); non-finite texels (NaN, ±Inf) never occlude (SPEC §3), so no
//   NaN comes out. s = 0 puts every sample in the centre's texel: a hard
//   shadow. r is used as given (not normalised): |r| != 1 scales the disk.
//   The disk comes in one of two ways:
//   - as a parameter, vec2 points[PN_POISSON_MAX_SAMPLES], with a runtime
//     count clamped to [0, PN_POISSON_MAX_SAMPLES] (arrays are passed by
//     value: drivers may copy it per call);
//   - read in place from a vec2 array the engine declares before the include
//     and names in PN_POISSON_DISK_ARRAY: a constant, e.g. the output of
//     `penumbra poisson --count 36` (`const vec2 PN_POISSON_DISK[36] =
//     vec2[](...);` with `#define PN_POISSON_DISK_ARRAY PN_POISSON_DISK`), or
//     a uniform-block member (`vec2 points[64]`, std140 stride 16: the layout
//     of a vec4 array's xy; `#define PN_POISSON_DISK_ARRAY pnDisk.points`);
//     the count is then clamped to [0, its length()].
//
// The call (PCSS as engines ship it, in one pass): PCSS's search width for
//   the receiver's depth (light_model.glsl: blockers as near as the near
//   plane), the blocker search with the blocker disk over it — no blocker:
//   lit, return 1 at once —, the penumbra of Eq. (1) from the blocker mean
//   times filterScale as the filter disk's diameter (pnFilterEntry,
//   pcss_regions.glsl), and PCF with the filter disk over it:
//     visibility = 1 - occluded fraction.
//   The disks are read in place from two arrays the engine declares and
//   names before the include: PN_POISSON_BLOCKER_DISK and
//   PN_POISSON_FILTER_DISK (`penumbra poisson --count 36 --seed ...`), or
//   PN_POISSON_DISK_ARRAY for both.
//
// use:
//   float pnPoissonPcss(sampler2D depthMap, PnLight light, vec3 receiver, PnPoissonPcssSettings settings,
//                       vec2 rotation)            receiver = (u, v, d) as pnLightProject gives;
//                                                 rotation = (1, 0), or pnPoissonRotation(angle) per pixel
//   PnPoissonPcssSettings pnPoissonPcssDefaults(float bias)   36 / 64 samples, filterScale 1
//   PnPoissonPcssResult pnPoissonPcssEstimate(... the same ...)  visibility, the regions, the mean
//   PnPoisson pnPoissonOcclusionDisk(sampler2D depthMap, vec2 centre, float diameter, float receiverDepth,
//                                    float bias, int count, vec2 rotation)   (with PN_POISSON_DISK_ARRAY)
//   PnPoisson pnPoissonAddSamplePlane(... the same ..., float threshold, vec2 gradient, PnPoisson sums)
//         with a receiver plane (receiver_plane.glsl): the texel q's threshold is
//         threshold + gradient · (q + 1/2 - centre)
//   PnPoisson pnPoissonAddSample(sampler2D depthMap, vec2 centre, float radius, vec2 offset, vec2 rotation,
//                                float threshold, PnPoisson sums)   one sample (radius = s / 2, threshold = t)
//   float pnPoissonBlockerMean(PnPoisson s)        depthSum / occluders, 0 without occluders
//   float pnPoissonOccludedFraction(PnPoisson s)   occluders / samples, 0 without samples
//   vec2  pnPoissonRotation(float angle)           (cos, sin) of an angle in radians
//   struct PnPoisson { float occluders; float depthSum; float samples; }
//   depthMap: linear light depth in .r (R32F or any float format), texelFetch only.
//
// options:
//   PN_POISSON_MAX_SAMPLES      size of the parameter array (64; poisson_pcss.h, shared with the runner)
//   PN_POISSON_BLOCKER_SAMPLES  default blocker-search count for callers (36; poisson_pcss.h)
//   PN_POISSON_PCF_SAMPLES      default PCF count for callers (64; poisson_pcss.h)
//   PN_POISSON_DISK_ARRAY       a vec2 array to read the disk from in place (undefined: none)
//   PN_POISSON_BLOCKER_DISK, PN_POISSON_FILTER_DISK   the call's two disks (default: PN_POISSON_DISK_ARRAY)
//
// cost: per sample one texelFetch, ~8 ALU operations; `count` samples per call,
//   independent of the disk's size.
//
// isa budget: vgprs 16, instructions 400, code 2048, scratch 0, loop 80, loops 160
//   (`penumbra isa --budgets`: the call as an engine compiles it, RDNA 2 wave64; docs/isa.md)

#ifndef PENUMBRA_POISSON_PCSS_GLSL
#define PENUMBRA_POISSON_PCSS_GLSL

#include "light_model.glsl"
#include "pcss_regions.glsl"
#include "poisson_pcss.h"
#include "receiver_plane.glsl"

struct PnPoisson {
  float occluders;  // samples with depth < dP - bias
  float depthSum;   // their depth sum
  float samples;    // samples taken
};

vec2 pnPoissonRotation(float angle) {
  return vec2(cos(angle), sin(angle));
}

float pnPoissonBlockerMean(PnPoisson s) {
  return s.occluders > 0.0 ? s.depthSum / s.occluders : 0.0;
}

float pnPoissonOccludedFraction(PnPoisson s) {
  return s.samples > 0.0 ? s.occluders / s.samples : 0.0;
}

// With a receiver plane (receiver_plane.glsl): the threshold at the sampled texel's centre q + 1/2 is
// threshold + gradient · (q + 1/2 - centre), the disk's centre being the receiver's (u, v).
PnPoisson pnPoissonAddSamplePlane(sampler2D depthMap, vec2 centre, float radius, vec2 offset, vec2 rotation,
                                  float threshold, vec2 gradient, PnPoisson sums) {
  vec2 o = vec2(rotation.x * offset.x - rotation.y * offset.y, rotation.y * offset.x + rotation.x * offset.y);
  vec2 p = centre + radius * o;
  sums.samples += 1.0;
  // Inside the map, compared as floats before any conversion (NaN and ±Inf fail).
  vec2 n = vec2(textureSize(depthMap, 0));
  if (!(all(greaterThanEqual(p, vec2(0.0))) && all(lessThan(p, n)))) return sums;
  vec2 q = floor(p);
  float d = texelFetch(depthMap, ivec2(q), 0).r;
  // pcf.glsl's pnPcfOccludes: NaN compares false, +Inf is never below, -Inf excluded (one compare).
  if (d < pnReceiverPlaneThreshold(threshold, gradient, centre, ivec2(q)) && d > uintBitsToFloat(0xff800000u)) {
    sums.occluders += 1.0;
    sums.depthSum += d;
  }
  return sums;
}

PnPoisson pnPoissonAddSample(sampler2D depthMap, vec2 centre, float radius, vec2 offset, vec2 rotation,
                             float threshold, PnPoisson sums) {
  return pnPoissonAddSamplePlane(depthMap, centre, radius, offset, rotation, threshold, vec2(0.0), sums);
}

#ifdef PN_POISSON_DISK_ARRAY
PnPoisson pnPoissonOcclusionDisk(sampler2D depthMap, vec2 centre, float diameter, float receiverDepth, float bias,
                                 int count, vec2 rotation) {
  PnPoisson sums = PnPoisson(0.0, 0.0, 0.0);
  float radius = 0.5 * diameter;
  float t = receiverDepth - bias;
  for (int i = 0; i < PN_POISSON_DISK_ARRAY.length(); ++i) {
    if (i >= count) break;
    sums = pnPoissonAddSample(depthMap, centre, radius, PN_POISSON_DISK_ARRAY[i], rotation, t, sums);
  }
  return sums;
}
#endif

#if defined(PN_POISSON_DISK_ARRAY) && !defined(PN_POISSON_BLOCKER_DISK)
#define PN_POISSON_BLOCKER_DISK PN_POISSON_DISK_ARRAY
#endif
#if defined(PN_POISSON_DISK_ARRAY) && !defined(PN_POISSON_FILTER_DISK)
#define PN_POISSON_FILTER_DISK PN_POISSON_DISK_ARRAY
#endif

#if defined(PN_POISSON_BLOCKER_DISK) && defined(PN_POISSON_FILTER_DISK)
struct PnPoissonPcssSettings {
  float bias;          // light-depth units: a sample occludes when its depth < d - bias
  float filterScale;   // c: filter diameter = c · penumbra
  int blockerSamples;  // first samples of PN_POISSON_BLOCKER_DISK, clamped to its length
  int filterSamples;   // first samples of PN_POISSON_FILTER_DISK
};

struct PnPoissonPcssResult {
  float visibility;   // 1 - occluded fraction; 1 when lit
  vec4 searchEntry;   // (d, x, y, s): s the search disk's diameter; s < 0: no surface
  vec4 filterEntry;   // s the filter disk's; s < 0: lit (no blocker)
  float blockerMean;  // 0 without a blocker
};

PnPoissonPcssSettings pnPoissonPcssDefaults(float bias) {
  return PnPoissonPcssSettings(bias, 1.0, PN_POISSON_BLOCKER_SAMPLES, PN_POISSON_PCF_SAMPLES);
}

PnPoisson pn_poissonBlockerSearch(sampler2D depthMap, vec4 entry, float bias, vec2 gradient, int count,
                                  vec2 rotation) {
  PnPoisson sums = PnPoisson(0.0, 0.0, 0.0);
  for (int i = 0; i < PN_POISSON_BLOCKER_DISK.length(); ++i) {
    if (i >= count) break;
    sums = pnPoissonAddSamplePlane(depthMap, entry.yz, 0.5 * entry.w, PN_POISSON_BLOCKER_DISK[i], rotation,
                                   entry.x - bias, gradient, sums);
  }
  return sums;
}

PnPoisson pn_poissonFilter(sampler2D depthMap, vec4 entry, float bias, vec2 gradient, int count, vec2 rotation) {
  PnPoisson sums = PnPoisson(0.0, 0.0, 0.0);
  for (int i = 0; i < PN_POISSON_FILTER_DISK.length(); ++i) {
    if (i >= count) break;
    sums = pnPoissonAddSamplePlane(depthMap, entry.yz, 0.5 * entry.w, PN_POISSON_FILTER_DISK[i], rotation,
                                   entry.x - bias, gradient, sums);
  }
  return sums;
}

PnPoissonPcssResult pnPoissonPcssEstimate(sampler2D depthMap, PnLight light, vec3 receiver, vec2 receiverPlane,
                                          PnPoissonPcssSettings s, vec2 rotation) {
  PnPoissonPcssResult r = PnPoissonPcssResult(1.0, pn_searchStart(light, vec4(receiver, 1.0)), vec4(0.0), 0.0);
  r.filterEntry = vec4(r.searchEntry.xyz, PN_REGION_LIT);
  if (pnEntryLit(r.searchEntry)) return r;
  PnPoisson blockers = pn_poissonBlockerSearch(depthMap, r.searchEntry, s.bias, receiverPlane, s.blockerSamples,
                                               rotation);
  bool hasBlocker = blockers.occluders > 0.0;
  r.blockerMean = pnPoissonBlockerMean(blockers);
  r.filterEntry = pnFilterEntry(light, r.searchEntry, r.blockerMean, hasBlocker, s.filterScale);
  if (pnEntryLit(r.filterEntry)) return r;  // no blocker: lit, no PCF
  r.visibility = 1.0 - pnPoissonOccludedFraction(pn_poissonFilter(depthMap, r.filterEntry, s.bias, receiverPlane,
                                                                 s.filterSamples, rotation));
  return r;
}

PnPoissonPcssResult pnPoissonPcssEstimate(sampler2D depthMap, PnLight light, vec3 receiver,
                                          PnPoissonPcssSettings s, vec2 rotation) {
  return pnPoissonPcssEstimate(depthMap, light, receiver, vec2(0.0), s, rotation);
}

float pnPoissonPcss(sampler2D depthMap, PnLight light, vec3 receiver, vec2 receiverPlane,
                    PnPoissonPcssSettings settings, vec2 rotation) {
  return pnPoissonPcssEstimate(depthMap, light, receiver, receiverPlane, settings, rotation).visibility;
}

float pnPoissonPcss(sampler2D depthMap, PnLight light, vec3 receiver, PnPoissonPcssSettings settings,
                    vec2 rotation) {
  return pnPoissonPcssEstimate(depthMap, light, receiver, settings, rotation).visibility;
}
#endif

#endif  // PENUMBRA_POISSON_PCSS_GLSL
