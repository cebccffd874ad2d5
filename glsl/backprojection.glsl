// backprojection.glsl — soft shadows by back-projection over the min/max mip
// chain: the fraction of the light a receiver sees, from the shadow map read
// as a height field, not a blocker average.
//
// description:
//   Issue 28 (Guennebaud, Barthe & Paulin 2006, their gap filling; Schwarz &
//   Stamminger 2007's bitmask of light samples). The shadow map is a surface:
//   texel (i, j) at linear light depth d is a flat patch, its square at depth
//   d; two 4-neighbours whose depths differ by at most `gap` texel widths
//   (pnLightTexelWorld at the nearer one) are one surface, joined by a wall
//   on their shared edge spanning the two depths — the gap rule, closing the
//   cracks between the patches of one sloped surface; a larger step is a
//   silhouette, left open (the map cannot tell contact from a gap: below).
//   The light is side × side stratified, jittered samples l in [-1/2, 1/2]²
//   of its square (backprojection.h; a square of width w_L at the map's
//   viewpoint, or the sun's square of spread S). The ray from the receiver
//   (u, v, dP) to sample l crosses depth z at texel
//       (u, v) + l · W(z),   W(z) = pnLightBlockerWindowTexels(light, dP, z)
//   (light_model.glsl: W(dP) = 0, growing toward the light). It is blocked
//   when it crosses a patch or a wall in front of the receiver (depth
//   < dP - bias): patch (i, j) iff l · W(d) lies in its square, a wall iff
//   the ray meets its edge's line at a window between W(deeper depth) and
//   W(d), inside the edge. Each blocked sample sets its bit; overlapping
//   patches set a bit once:
//       visibility = 1 - (bits set) / side².
//   The traversal walks the aligned min/max mip chain (minmax_mip.glsl) from
//   its top, depth first, with an explicit stack:
//     - a node with min + bias >= dP cannot occlude: skipped;
//     - a node the rays cannot reach (its square outside ± W(min) / 2 around
//       the receiver) is skipped;
//     - a texel (level 0) is back-projected exactly: its patch and its walls to
//       its deeper neighbours of the same surface (four fetches);
//     - a node whose depth range is below `tolerance` · (dP - min) stands as one
//       patch at the middle of its range, without walls; 0: every node
//       resolved to its texels;
//     - past `budget` nodes, every node left on the stack stands as one patch
//       likewise (an estimate of what remains, never dropped).
//   With tolerance 0 and a budget that is not reached, the result is the
//   fraction of the same samples whose ray to the receiver crosses the map's
//   surface — exactly (runner/reference/backprojection_reference.cpp).
//
// use:
//   PnBackprojectionSettings { int side; float tolerance; int budget; float gap; }
//   PnBackprojectionSettings pnBackprojectionDefaults()   side 8 (64 samples), tolerance 0.05,
//         budget PN_BACKPROJECTION_DEFAULT_BUDGET, gap 3 texel widths
//   float pnBackprojection(sampler2D mip, PnLight light, vec3 receiver, float bias, PnBackprojectionSettings s)
//         receiver = (u, v, d) as pnLightProject gives; mip: the map's min/max chain
//         (minmax_mip.glsl); returns the visibility in [0, 1] (1: no surface, lit)
//   PnBackprojection pnBackprojectionWork(sampler2D mip, PnLight light, vec3 receiver, float bias,
//         PnBackprojectionSettings s)   the same with its work: (visibility, blocked samples,
//         nodes visited, patches that stood for nodes)
//   vec2 pnBackprojectionSample(int k, int side)   light sample k, in [-1/2, 1/2]²
//
// cost: per node visited one fetch, per texel four more (its neighbours); per
//   patch a point test per sample (side² of them), per wall a line test. Bounded by `budget` nodes and a
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
  float gap;        // neighbours whose depths differ by <= gap texel widths are one surface (a wall joins them)
};

struct PnBackprojection {
  float visibility;
  float blocked;   // samples blocked
  float nodes;     // nodes visited
  float patches;   // nodes that stood as one patch (tolerance or budget)
};

PnBackprojectionSettings pnBackprojectionDefaults() {
  return PnBackprojectionSettings(PN_BACKPROJECTION_DEFAULT_SIDE, PN_BACKPROJECTION_DEFAULT_TOLERANCE,
                                  PN_BACKPROJECTION_DEFAULT_BUDGET, PN_BACKPROJECTION_DEFAULT_GAP);
}

vec2 pnBackprojectionSample(int k, int side) {
  uint h = PN_BACKPROJECTION_HASH(uint(k));
  int bits = PN_BACKPROJECTION_JITTER_BITS;
  float unit = 1.0 / float(1 << bits);
  vec2 jitter = vec2(float(h >> uint(32 - bits)), float(h & ((1u << uint(bits)) - 1u))) * unit;
  vec2 stratum = vec2(float(k % side), float(k / side));
  return (stratum + jitter) * (1.0 / float(side)) - 0.5;
}

// Sets the bit of every sample whose ray crosses the patch [lo, hi] (texels, relative to the
// receiver) at the depth whose window is `window`: the point l · window inside the box (closed).
void pnBackprojectPatch(vec2 lo, vec2 hi, float window, int side, inout uint mask[PN_BACKPROJECTION_MASK_WORDS]) {
  int count = side * side;
  for (int k = 0; k < count; ++k) {
    vec2 p = pnBackprojectionSample(k, side) * window;
    if (all(greaterThanEqual(p, lo)) && all(lessThanEqual(p, hi))) mask[k >> 5] |= 1u << uint(k & 31);
  }
}

// Sets the bit of every sample whose ray crosses the wall on the line where axis `a` equals `edge`,
// between `from` and `to` on the other axis, at windows in [near, far] (the wall's depths).
void pnBackprojectWall(int a, float edge, float from, float to, float near, float far, int side,
                       inout uint mask[PN_BACKPROJECTION_MASK_WORDS]) {
  int count = side * side;
  int b = 1 - a;
  for (int k = 0; k < count; ++k) {
    vec2 l = pnBackprojectionSample(k, side);
    if (l[a] == 0.0) continue;  // parallel to the wall
    float w = edge / l[a];
    float across = l[b] * w;
    if (w >= near && w <= far && across >= from && across <= to) mask[k >> 5] |= 1u << uint(k & 31);
  }
}

// Texel `q` of depth d (lo, hi: its square relative to the receiver): its patch, and its walls down
// to each deeper neighbour the surface continues into (depth step <= gap texel widths).
void pnBackprojectTexel(sampler2D mip, PnLight light, vec3 receiver, float bias, float gap, ivec2 q, float d,
                        vec2 lo, vec2 hi, int side, inout uint mask[PN_BACKPROJECTION_MASK_WORDS]) {
  float dP = receiver.z;
  float window = pnLightBlockerWindowTexels(light, dP, d);
  pnBackprojectPatch(lo, hi, window, side, mask);
  float step = gap * pnLightTexelWorld(light, d);
  for (int n = 0; n < 4; ++n) {
    ivec2 dir = n == 0 ? ivec2(1, 0) : n == 1 ? ivec2(-1, 0) : n == 2 ? ivec2(0, 1) : ivec2(0, -1);
    float neighbour = pnMipFetch(mip, 0, q + dir).x;  // +Inf outside the map
    if (!(neighbour > d) || !(neighbour - d <= step)) continue;
    float deepest = min(neighbour, dP - bias);  // only what lies in front of the receiver blocks
    if (!(deepest > d)) continue;
    int a = dir.x != 0 ? 0 : 1;
    float edge = (dir[a] > 0 ? hi : lo)[a];
    pnBackprojectWall(a, edge, lo[1 - a], hi[1 - a], pnLightBlockerWindowTexels(light, dP, deepest), window, side,
                      mask);
  }
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
    // Every patch and wall of the node lies at a depth >= its min: at most W(min) from the receiver.
    float reach = pnLightBlockerWindowTexels(light, dP, range.x);
    int size = 1 << node.x;
    vec2 lo = vec2(node.yz * size) - receiver.xy, hi = lo + float(size);
    if (any(greaterThan(lo, vec2(0.5 * reach))) || any(lessThan(hi, vec2(-0.5 * reach)))) continue;
    if (node.x == 0) {
      pnBackprojectTexel(mip, light, receiver, bias, s.gap, node.yz, range.x, lo, hi, side, mask);
      continue;
    }
    bool resolve = visited < budget && range.y - range.x >= s.tolerance * (dP - range.x) &&
                   top + 4 <= PN_BACKPROJECTION_STACK;
    if (resolve) {
      for (int c = 3; c >= 0; --c) stack[top++] = ivec3(node.x - 1, node.yz * 2 + ivec2(c & 1, c >> 1));
      continue;
    }
    // A node standing as one patch at the middle of its range (in front of the receiver).
    result.patches += 1.0;
    float depth = 0.5 * (range.x + min(range.y, dP - bias));
    pnBackprojectPatch(lo, hi, pnLightBlockerWindowTexels(light, dP, depth), side, mask);
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
