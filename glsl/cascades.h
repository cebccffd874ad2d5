// cascades.h — the formulas of parallel-split (cascaded) shadow maps that
// glsl/cascades.glsl and the runner share (seed 003 §3, docs/modules/cascades.md):
// where the view frustum is split, the first split's enlargement, the
// bounding sphere of a slice and the texel snap of a cascade's centre.
//
// Written once, in the subset that GLSL and C++ with glm have in common:
// float, int and vec2 arithmetic, the built-ins both name alike (pow, log2,
// min, max, clamp, floor, sqrt), f-suffixed literals, loops with a constant
// bound, no const locals, no out parameters. cascades.glsl includes it as
// GLSL; the runner includes it inside a namespace that says
// `using namespace glm;` (runner/cascades/cascade_math.h), so the splits the
// runner fits its cascades to are the splits a shader computes, from the same
// text. An engine may define the PN_CASCADE_* constants before the include.
//
// Inputs: camera near n and far f (view depths, 0 < n < f), split count m
// (1 ... PN_CASCADES_MAX), split index i (0 ... m: C_0 = n, C_m = f).

#ifndef PENUMBRA_CASCADES_H
#define PENUMBRA_CASCADES_H

// What precedes each function: nothing in GLSL; `inline` where C++ includes the header.
#ifndef PN_CASCADE_FUNCTION
#define PN_CASCADE_FUNCTION
#endif

// Most cascades a module handles (the loop bound; the splits travel as one vec4).
#ifndef PN_CASCADES_MAX
#define PN_CASCADES_MAX 4
#endif

// The adaptive lambda: PN_CASCADE_LAMBDA_SMALL for f / n <= 10^PN_CASCADE_LAMBDA_SMALL_DECADES,
// PN_CASCADE_LAMBDA_LARGE for f / n >= 10^PN_CASCADE_LAMBDA_LARGE_DECADES, linear in
// log10(f / n) between (seed 003 §3.1: lambda ~0.6 for small scenes, 1 for large ones).
#ifndef PN_CASCADE_LAMBDA_SMALL
#define PN_CASCADE_LAMBDA_SMALL 0.6f
#endif
#ifndef PN_CASCADE_LAMBDA_LARGE
#define PN_CASCADE_LAMBDA_LARGE 1.0f
#endif
#ifndef PN_CASCADE_LAMBDA_SMALL_DECADES
#define PN_CASCADE_LAMBDA_SMALL_DECADES 2.0f
#endif
#ifndef PN_CASCADE_LAMBDA_LARGE_DECADES
#define PN_CASCADE_LAMBDA_LARGE_DECADES 3.0f
#endif

// The gap g between neighbouring splits (the seed's delta-bias): split i reaches at most
// (1 - g) of the way from n to split i + 1. Clamped to [PN_CASCADE_GAP_MIN, PN_CASCADE_GAP_MAX].
#ifndef PN_CASCADE_GAP
#define PN_CASCADE_GAP 0.1f
#endif
#define PN_CASCADE_GAP_MIN 0.001f
#define PN_CASCADE_GAP_MAX 0.9f

// The share of a cascade's depth range, at its far end, over which it blends into the next.
#ifndef PN_CASCADE_BLEND_BAND
#define PN_CASCADE_BLEND_BAND 0.1f
#endif

// lambda from the depth ratio f / n; 0.6 (the small-scene weight) when n or f is unusable.
PN_CASCADE_FUNCTION float pnCascadeAdaptiveLambda(float near, float far) {
  if (!(near > 0.0f) || !(far > near)) return PN_CASCADE_LAMBDA_SMALL;
  float decades = log2(far / near) * 0.30102999566f;  // log10(f / n)
  float t = (decades - PN_CASCADE_LAMBDA_SMALL_DECADES) /
            (PN_CASCADE_LAMBDA_LARGE_DECADES - PN_CASCADE_LAMBDA_SMALL_DECADES);
  return PN_CASCADE_LAMBDA_SMALL + (PN_CASCADE_LAMBDA_LARGE - PN_CASCADE_LAMBDA_SMALL) * clamp(t, 0.0f, 1.0f);
}

// The practical split scheme (seed 003 Eq. 7):
//   C_i = lambda n (f / n)^(i / m) + (1 - lambda) (n + (f - n) i / m),
// exactly n for i <= 0 and f for i >= m; m is clamped to [1, PN_CASCADES_MAX].
PN_CASCADE_FUNCTION float pnCascadePracticalSplit(float lambda, float near, float far, int i, int count) {
  int m = clamp(count, 1, PN_CASCADES_MAX);
  if (i <= 0) return near;
  if (i >= m) return far;
  float t = float(i) / float(m);
  float logarithmic = near * pow(far / near, t);
  float even = near + (far - near) * t;
  return lambda * logarithmic + (1.0f - lambda) * even;
}

// The factor k_i of split i (i >= 1) for a first-split enlargement k (seed 003 §3.2):
// k_i = 1 + F_i with F_i = (k - 1) / 2^(i - 1), the progression that halves from one
// split to the next. k < 1 (or NaN) counts as 1: no enlargement. k_i / k_(i+1) < 2.
PN_CASCADE_FUNCTION float pnCascadeEnlargement(float k, int i) {
  float excess = (k > 1.0f) ? k - 1.0f : 0.0f;
  return 1.0f + excess / float(1 << clamp(i - 1, 0, 30));
}

// The hybrid split (seed 003 §3.2): each inner split enlarged by its factor,
//   E_i = n + (C_i - n) k_i  (0 < i < m),  E_m = f,
// then held below the next one by the gap g:
//   C'_m = f,  C'_i = n + min(E_i - n, (1 - g) (C'_(i+1) - n)),
// which guarantees n < C'_1 < ... < C'_(m-1) < f for any k and lambda in [0, 1].
// k = 1 gives the practical split wherever it already keeps the gap.
PN_CASCADE_FUNCTION float pnCascadeHybridSplit(float lambda, float near, float far, int i, int count, float k, float gap) {
  int m = clamp(count, 1, PN_CASCADES_MAX);
  if (i <= 0) return near;
  if (i >= m) return far;
  float keep = 1.0f - clamp(gap, PN_CASCADE_GAP_MIN, PN_CASCADE_GAP_MAX);
  float reach = far - near;  // C'_j - n, from j = m down to i
  for (int j = PN_CASCADES_MAX - 1; j >= 1; --j) {
    if (j >= m || j < i) continue;
    float enlarged = (pnCascadePracticalSplit(lambda, near, far, j, m) - near) * pnCascadeEnlargement(k, j);
    reach = min(enlarged, keep * reach);
  }
  return near + reach;
}

// The smallest sphere around the slice [a, b] of a view frustum (view depths
// 0 < a < b) whose corners lie at radial distance z * tanDiagonal from the
// axis at depth z (tanDiagonal = sqrt(tan^2(fovX / 2) + tan^2(fovY / 2))):
// centred on the axis at depth c = min((a + b)(1 + t^2) / 2, b), where the
// near and far corners are equally far, or at the far face's centre when
// that lies beyond b. Returns (c, radius). The radius depends on a, b and the
// field of view only, never on where the camera looks: a stable cascade's
// extent does not change as the camera turns.
PN_CASCADE_FUNCTION vec2 pnCascadeSliceSphere(float sliceNear, float sliceFar, float tanDiagonal) {
  float t2 = tanDiagonal * tanDiagonal;
  float centre = min(0.5f * (sliceNear + sliceFar) * (1.0f + t2), sliceFar);
  float nearRadius2 = (centre - sliceNear) * (centre - sliceNear) + sliceNear * sliceNear * t2;
  float farRadius2 = (sliceFar - centre) * (sliceFar - centre) + sliceFar * sliceFar * t2;
  return vec2(centre, sqrt(max(nearRadius2, farRadius2)));
}

// A stable cascade's centre in whole texels: the light-space (x, y) of the
// sphere's centre divided by the texel size and rounded to the nearest
// integer. The cascade spans (snapped * texelSize) +- radius, so every world
// point's map position moves by whole texels when the camera moves.
PN_CASCADE_FUNCTION vec2 pnCascadeSnapTexels(vec2 centreLight, float texelSize) {
  return floor(centreLight / texelSize + vec2(0.5f, 0.5f));
}

#endif  // PENUMBRA_CASCADES_H
