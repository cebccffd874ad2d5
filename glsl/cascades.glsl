// cascades.glsl — parallel-split (cascaded) shadow maps: where the view
// frustum is split, which cascade shades a receiver, and how neighbouring
// cascades are blended (seed 003 §3; docs/modules/cascades.md).
//
// description:
//   The splits, the first split's enlargement, the slice's bounding sphere
//   and the texel snap are in cascades.h (shared with the runner, which fits
//   each cascade's orthographic light projection with them):
//     pnCascadeAdaptiveLambda, pnCascadePracticalSplit (Eq. 7),
//     pnCascadeEnlargement, pnCascadeHybridSplit (the enlarged first split
//     with the progression F_i and the gap), pnCascadeSliceSphere,
//     pnCascadeSnapTexels.
//   Selection: a receiver at view depth z (distance along the camera's axis)
//   belongs to cascade i when C_i <= z < C_(i+1) — the number of split far
//   ends at or before z. Its depth range's last `band` share,
//   [C_(i+1) - band (C_(i+1) - C_i), C_(i+1)), is the transition band: there the
//   next cascade's visibility is mixed in with weight
//     w = (z - bandStart) / (C_(i+1) - bandStart),
//   rising linearly from 0 to 1, so the visibility is continuous across the
//   split (the seed's linear blend over the overlap). The runner fits cascade
//   i + 1 to [bandStart_i, C_(i+2)], so both cascades hold the band's receivers.
//   The last cascade fades into "lit" over its own band when fadeLast is set
//   (no hard edge where the shadows end) and has weight 0 otherwise.
//   z < n counts as cascade 0; z >= f, NaN or +Inf gives no cascade.
//
// use:
//   PnCascadeChoice pnCascadeSelect(float viewDepth, float near, vec4 splitFar, int count,
//                                   float band, bool fadeLast)
//   float pnCascadeBlend(float visibility, float nextVisibility, PnCascadeChoice choice)
//   struct PnCascadeChoice { int index; int next; float nextWeight; }
//   splitFar[i] = C_(i+1), the far end of cascade i (i < count); near = C_0;
//   count is clamped to [1, PN_CASCADES_MAX]; band to [0, 1].
//   index == count: no cascade (lit); next == count: "lit" (nextVisibility = 1).
//
// cost: PN_CASCADES_MAX compares and one division per receiver.

#ifndef PENUMBRA_CASCADES_GLSL
#define PENUMBRA_CASCADES_GLSL

#include "cascades.h"

struct PnCascadeChoice {
  int index;         // the receiver's cascade; count: none (beyond the last split, NaN)
  int next;          // the cascade blended in: index + 1 (count: lit)
  float nextWeight;  // its weight, 0 outside the transition band
};

PnCascadeChoice pnCascadeSelect(float viewDepth, float near, vec4 splitFar, int count, float band, bool fadeLast) {
  int m = clamp(count, 1, PN_CASCADES_MAX);
  if (!(viewDepth < splitFar[m - 1])) return PnCascadeChoice(m, m, 0.0);  // beyond f, +Inf, NaN
  int index = 0;
  for (int i = 0; i < PN_CASCADES_MAX; ++i)
    if (i < m && splitFar[i] <= viewDepth) index = i + 1;
  float end = splitFar[index];
  float start = (index == 0) ? near : splitFar[index - 1];
  float bandStart = end - clamp(band, 0.0, 1.0) * (end - start);
  float weight = (viewDepth > bandStart) ? clamp((viewDepth - bandStart) / (end - bandStart), 0.0, 1.0) : 0.0;
  if (index == m - 1 && !fadeLast) weight = 0.0;
  return PnCascadeChoice(index, index + 1, weight);
}

float pnCascadeBlend(float visibility, float nextVisibility, PnCascadeChoice choice) {
  return mix(visibility, nextVisibility, choice.nextWeight);
}

#endif  // PENUMBRA_CASCADES_GLSL
