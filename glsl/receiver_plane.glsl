// receiver_plane.glsl — receiver-plane depth bias: compare each shadow-map
// texel with the receiver's surface at that texel, not with one depth.
//
// description:
//   A receiver at (u, v, d) (shadow-map texels, continuous, and linear light
//   depth) lies on a surface; near it the surface's light depth, as a function
//   of the map position q, is to first order the plane
//     z(q) = d + g · (q - (u, v)),   g = (∂d/∂u, ∂d/∂v)   (light depth per texel).
//   g comes from two steps of the receiver across the screen, a = (du, dv, dd)
//   and b (dFdx and dFdy of (u, v, d) in a fragment shader, or differences of
//   G-buffer neighbours): g solves g · (a.u, a.v) = a.d and g · (b.u, b.v) =
//   b.d (the plane through the three points), by Cramer's rule. When the
//   steps are parallel, |a.u b.v - a.v b.u| < PN_RECEIVER_PLANE_MIN_SINE ·
//   |(a.u, a.v)| |(b.u, b.v)| (the surface edge-on to the light or the
//   camera, a zero step), or the result is not finite, g = 0. |g| is then clamped to maxSlope (light depth per
//   texel): a receiver steeper than that is not trusted to be a plane.
//   A texel q (covering [q, q + 1)) occludes the receiver when its depth is
//   below the plane at its centre, never behind the receiver, minus the
//   constant bias:
//     d(q) < min(d, z(q + 1/2)) - bias
//   so a sloped receiver needs no bias for its slope (no acne: its texels up
//   the slope stand nearer the light), and what lies down the slope is
//   judged as without a plane: a blocker is nearer the light than the
//   receiver it shadows, and the plane extrapolated far down a slope (or
//   steep near a silhouette) would call the ground beyond it a blocker
//   (measured: boxes ×1 at 256², MAE 0.0092 with the two-sided plane,
//   0.0081 with this one and without a plane).
//   Over a rectangle of texels [o, o + s) the plane's extremes at the texel
//   centres are z(o + s/2) ± (|g.x| (s.x - 1) + |g.y| (s.y - 1)) / 2
//   (pnReceiverPlaneRange): what a node of a hierarchy is decided against
//   (its thresholds' range: both extremes minus the bias, capped at d - bias).
//   First order: in a perspective map a world plane's 1/d, not d, is affine
//   in q, so far from the receiver z(q) bends away from the surface; the
//   constant bias covers what that leaves within the filter region.
//
// use:
//   vec2  pnReceiverPlaneGradient(vec3 stepA, vec3 stepB, float maxSlope)   g, or 0
//   vec2  pnReceiverPlaneFromNeighbours(vec4 centre, vec4 left, vec4 right, vec4 below, vec4 above,
//                                       float maxSlope)
//         G-buffer entries (u, v, d, valid); per axis the one-sided step with the smaller |Δd| between
//         valid entries (the side that stays on the receiver's surface at a depth edge); none: g = 0
//   float pnReceiverPlaneDepth(vec3 receiver, vec2 gradient, vec2 q)    z(q)
//   vec2  pnReceiverPlaneRange(vec3 receiver, vec2 gradient, ivec2 origin, ivec2 size)   (min, max)
//         of z over the centres of the texels [origin, origin + size)
//   float pnReceiverPlaneThreshold(float threshold, vec2 gradient, vec2 centre, ivec2 q)
//         the shadow test's threshold at texel q: min(threshold, threshold + g · (q + 1/2 - centre)),
//         threshold = the receiver's depth minus the bias, centre = its (u, v); g = 0 returns
//         `threshold` itself
//   vec2  pnReceiverPlaneThresholdRange(float threshold, vec2 gradient, vec2 centre, ivec2 lo, ivec2 hi)
//         its (min, max) over the texels [lo, hi), widened by the float rounding of both, capped at
//         `threshold` (g = 0: (threshold, threshold)): a node decided against the range agrees with
//         each of its texels' own thresholds
//
// options:
//   PN_RECEIVER_PLANE_MIN_SINE   the parallel steps' bound (0.01; receiver_plane.h)
//
// cost: the gradient: ~12 ALU operations and a division; a texel's threshold: one dot product.

#ifndef PENUMBRA_RECEIVER_PLANE_GLSL
#define PENUMBRA_RECEIVER_PLANE_GLSL

#include "receiver_plane.h"

vec2 pnReceiverPlaneGradient(vec3 a, vec3 b, float maxSlope) {
  float det = a.x * b.y - a.y * b.x;
  if (!(abs(det) > PN_RECEIVER_PLANE_MIN_SINE * length(a.xy) * length(b.xy))) return vec2(0.0);  // NaN fails too
  vec2 g = vec2(a.z * b.y - b.z * a.y, b.z * a.x - a.z * b.x) / det;
  float slope = length(g);
  if (isnan(slope) || isinf(slope)) return vec2(0.0);
  return slope > maxSlope ? g * (maxSlope / slope) : g;
}

// The step from `centre` toward the neighbour of the two (`minus` one pixel before, `plus` after) whose
// depth differs less, as (u, v, d) per pixel; 0 when neither is valid.
vec3 pn_receiverPlaneStep(vec4 centre, vec4 minus, vec4 plus) {
  bool useMinus = minus.w != 0.0, usePlus = plus.w != 0.0;
  if (useMinus && usePlus) {
    usePlus = abs(plus.z - centre.z) <= abs(centre.z - minus.z);
    useMinus = !usePlus;
  }
  if (usePlus) return plus.xyz - centre.xyz;
  if (useMinus) return centre.xyz - minus.xyz;
  return vec3(0.0);
}

vec2 pnReceiverPlaneFromNeighbours(vec4 centre, vec4 left, vec4 right, vec4 below, vec4 above, float maxSlope) {
  return pnReceiverPlaneGradient(pn_receiverPlaneStep(centre, left, right), pn_receiverPlaneStep(centre, below, above),
                                 maxSlope);
}

float pnReceiverPlaneDepth(vec3 receiver, vec2 gradient, vec2 q) {
  return receiver.z + dot(gradient, q - receiver.xy);
}

vec2 pnReceiverPlaneRange(vec3 receiver, vec2 gradient, ivec2 origin, ivec2 size) {
  vec2 s = vec2(size);
  float mid = pnReceiverPlaneDepth(receiver, gradient, vec2(origin) + 0.5 * s);
  float extent = 0.5 * (abs(gradient.x) * max(s.x - 1.0, 0.0) + abs(gradient.y) * max(s.y - 1.0, 0.0));
  return vec2(mid - extent, mid + extent);
}

// No plane (gradient 0) returns the threshold itself, whatever the centre (a NaN one too). The
// plane only lowers it: down the slope the receiver's own depth decides (a blocker is nearer).
float pnReceiverPlaneThreshold(float threshold, vec2 gradient, vec2 centre, ivec2 q) {
  return all(equal(gradient, vec2(0.0))) ? threshold : min(threshold, threshold + dot(gradient, vec2(q) + 0.5 - centre));
}

vec2 pnReceiverPlaneThresholdRange(float threshold, vec2 gradient, vec2 centre, ivec2 lo, ivec2 hi) {
  if (all(equal(gradient, vec2(0.0)))) return vec2(threshold);
  vec2 range = pnReceiverPlaneRange(vec3(centre, threshold), gradient, lo, hi - lo);
  // Each texel's threshold rounds q + 1/2 - centre (|q| + |centre| large), the products and the sum;
  // so does the range: 2^-18 of the magnitudes involved bounds both (a few float ulps each).
  vec2 magnitude = abs(vec2(lo)) + abs(vec2(hi)) + 2.0 * abs(centre);
  float mid = 0.5 * (range.x + range.y);
  float slack = exp2(-18.0) * (abs(threshold) + abs(mid) + dot(abs(gradient), magnitude));
  return min(range + vec2(-slack, slack), vec2(threshold));
}

#endif  // PENUMBRA_RECEIVER_PLANE_GLSL
