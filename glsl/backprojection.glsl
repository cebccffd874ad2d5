// backprojection.glsl — soft shadows by back-projection over the min/max mip
// chain: the fraction of the light a receiver sees, from the shadow map read
// as a height field, not a blocker average.
//
// description:
//   Issue 28 (Guennebaud, Barthe & Paulin 2006; Schwarz & Stamminger 2007's
//   bitmask of light samples). The shadow map is a height field: texel (i, j)
//   at linear light depth d is a column, solid from depth d away from the
//   light (what the map cannot see behind a surface it takes as filled: this
//   is the gap rule, below). The light is side × side stratified, jittered
//   samples l in [-1/2, 1/2]² of its square (backprojection.h; a square of
//   width w_L at the map's viewpoint, or the sun's square of spread S). The
//   ray from the receiver (u, v, dP) to sample l crosses depth z at texel
//       (u, v) + l · W(z),   W(z) = pnLightBlockerWindowTexels(light, dP, z)
//   (light_model.glsl: W(dP) = 0, growing toward the light). It is blocked
//   when it passes below some column: at a point of depth z inside texel
//   (i, j)'s square with d < z - bias. W falls with z, so that holds iff the
//   segment from (0, 0) to l · W(d + bias) meets the square
//   Q = [i - u, i + 1 - u] × [j - v, j + 1 - v]: the texel's patch
//   back-projected onto the light and everything beyond it, away from the
//   receiver — the patch closes the gap to its neighbours by its column's
//   wall, so neighbouring texels at different depths leave no crack between
//   their back-projections (the micro-quads' job, done by the columns).
//   Each blocked sample sets its bit; overlapping patches set a bit once:
//       visibility = 1 - (bits set) / side².
//   The traversal walks the aligned min/max mip chain (minmax_mip.glsl) from
//   its top, depth first, with an explicit stack:
//     - a node with min + bias >= dP cannot occlude: skipped;
//     - a node the segments cannot reach (its square outside ± W(min + bias) / 2
//       around the receiver) is skipped;
//     - a texel (level 0) is back-projected exactly against every sample;
//     - a node whose depth range is within `tolerance` · (dP - min) stands as one
//       patch at the middle of its range; 0: every node resolved to its texels;
//     - past `budget` nodes, every node left on the stack stands as one patch
//       likewise (an estimate of what remains, never dropped).
//   With tolerance 0 and a budget that is not reached, the result is the
//   fraction of the same samples whose segment to the receiver passes below the
//   height field — exactly (runner/reference/backprojection_reference.cpp).
//
// use:
//   PnBackprojectionSettings { int side; float tolerance; int budget; }
//   PnBackprojectionSettings pnBackprojectionDefaults()   side 8 (64 samples), tolerance 0.05,
//         budget PN_BACKPROJECTION_DEFAULT_BUDGET
//   float pnBackprojection(sampler2D mip, PnLight light, vec3 receiver, float bias, PnBackprojectionSettings s)
//         receiver = (u, v, d) as pnLightProject gives; mip: the map's min/max chain
//         (minmax_mip.glsl); returns the visibility in [0, 1] (1: no surface, lit)
//   PnBackprojection pnBackprojectionWork(sampler2D mip, PnLight light, vec3 receiver, float bias,
//         PnBackprojectionSettings s)   the same with its work: (visibility, blocked samples,
//         nodes visited, patches that stood for nodes)
//   vec2 pnBackprojectionSample(int k, int side)   light sample k, in [-1/2, 1/2]²
//
// cost: per node visited one fetch; per texel or patch back-projected a
//   slab test per sample (side² of them). Bounded by `budget` nodes and a
//   stack of 48; what bounds it in practice is the number of occluding
//   texels whose segments reach: the penumbra's area in texels.

#ifndef PENUMBRA_BACKPROJECTION_GLSL
#define PENUMBRA_BACKPROJECTION_GLSL

#include "backprojection.h"
#include "light_model.glsl"
#include "minmax_mip.glsl"

#define PN_BACKPROJECTION_STACK 48

struct PnBackprojectionSettings {
  int side;         // samples side × side (4, 8 or 16)
  float tolerance;  // a node of depth range <= tolerance · (dP - min) is one patch; 0: texels only
  int budget;       // nodes visited before the rest stand as patches
};

struct PnBackprojection {
  float visibility;
  float blocked;   // samples blocked
  float nodes;     // nodes visited
  float patches;   // nodes that stood as one patch (tolerance or budget)
};

PnBackprojectionSettings pnBackprojectionDefaults() {
  return PnBackprojectionSettings(PN_BACKPROJECTION_DEFAULT_SIDE, PN_BACKPROJECTION_DEFAULT_TOLERANCE,
                                  PN_BACKPROJECTION_DEFAULT_BUDGET);
}

vec2 pnBackprojectionSample(int k, int side) {
  uint h = PN_BACKPROJECTION_HASH(uint(k));
  int bits = PN_BACKPROJECTION_JITTER_BITS;
  float unit = 1.0 / float(1 << bits);
  vec2 jitter = vec2(float(h >> uint(32 - bits)), float(h & ((1u << uint(bits)) - 1u))) * unit;
  vec2 stratum = vec2(float(k % side), float(k / side));
  return (stratum + jitter) * (1.0 / float(side)) - 0.5;
}

// Whether the segment from (0, 0) to `e` meets the box [lo, hi] (closed).
bool pnBackprojectionSegmentHitsBox(vec2 e, vec2 lo, vec2 hi) {
  float enter = 0.0, leave = 1.0;
  for (int a = 0; a < 2; ++a) {
    if (e[a] == 0.0) {
      if (lo[a] > 0.0 || hi[a] < 0.0) return false;
    } else {
      float t0 = lo[a] / e[a], t1 = hi[a] / e[a];
      enter = max(enter, min(t0, t1));
      leave = min(leave, max(t0, t1));
    }
  }
  return enter <= leave;
}

// Sets the bit of every sample whose segment l · window meets the box [lo, hi] (texels, relative
// to the receiver).
void pnBackprojectBox(vec2 lo, vec2 hi, float window, int side, inout uint mask[PN_BACKPROJECTION_MASK_WORDS]) {
  int count = side * side;
  for (int k = 0; k < count; ++k)
    if (pnBackprojectionSegmentHitsBox(pnBackprojectionSample(k, side) * window, lo, hi))
      mask[k >> 5] |= 1u << uint(k & 31);
}

PnBackprojection pnBackprojectionWork(sampler2D mip, PnLight light, vec3 receiver, float bias,
                                      PnBackprojectionSettings s) {
  PnBackprojection result = PnBackprojection(1.0, 0.0, 0.0, 0.0);
  int side = clamp(s.side, PN_BACKPROJECTION_MIN_SIDE, PN_BACKPROJECTION_MAX_SIDE);
  int count = side * side;
  float dP = receiver.z;
  if (!(dP > 0.0) || isinf(dP)) return result;
  uint mask[PN_BACKPROJECTION_MASK_WORDS];
  for (int w = 0; w < PN_BACKPROJECTION_MASK_WORDS; ++w) mask[w] = 0u;
  int budget = clamp(s.budget, 1, PN_BACKPROJECTION_MAX_BUDGET);
  // The stack of nodes still to visit: (level, node x, node y).
  ivec3 stack[PN_BACKPROJECTION_STACK];
  int top = 0;
  stack[top++] = ivec3(pnMipMaxLevel(mip), 0, 0);
  int visited = 0;
  for (int step = 0; step < PN_BACKPROJECTION_MAX_BUDGET + PN_BACKPROJECTION_STACK && top > 0; ++step) {
    ivec3 node = stack[--top];
    vec2 range = pnMipFetch(mip, node.x, node.yz);
    ++visited;
    if (!(range.x + bias < dP)) continue;  // nothing in it can occlude (or no texel: +Inf)
    float reach = pnLightBlockerWindowTexels(light, dP, range.x + bias);
    int size = 1 << node.x;
    vec2 lo = vec2(node.yz * size) - receiver.xy, hi = lo + float(size);
    if (any(greaterThan(lo, vec2(0.5 * reach))) || any(lessThan(hi, vec2(-0.5 * reach)))) continue;
    bool resolve = node.x > 0 && visited < budget && range.y - range.x > s.tolerance * (dP - range.x) &&
                   top + 4 <= PN_BACKPROJECTION_STACK;
    if (resolve) {
      for (int c = 3; c >= 0; --c) stack[top++] = ivec3(node.x - 1, node.yz * 2 + ivec2(c & 1, c >> 1));
      continue;
    }
    // A texel, or a node standing as one patch at the middle of its range.
    float depth = node.x == 0 ? range.x : 0.5 * (range.x + min(range.y, dP - bias));
    if (node.x > 0) result.patches += 1.0;
    pnBackprojectBox(lo, hi, pnLightBlockerWindowTexels(light, dP, depth + bias), side, mask);
  }
  int blocked = 0;
  for (int w = 0; w < PN_BACKPROJECTION_MASK_WORDS; ++w) blocked += bitCount(mask[w]);
  result.blocked = float(blocked);
  result.visibility = 1.0 - float(blocked) / float(count);
  result.nodes = float(visited);
  return result;
}

float pnBackprojection(sampler2D mip, PnLight light, vec3 receiver, float bias, PnBackprojectionSettings s) {
  return pnBackprojectionWork(mip, light, receiver, bias, s).visibility;
}

#endif  // PENUMBRA_BACKPROJECTION_GLSL
