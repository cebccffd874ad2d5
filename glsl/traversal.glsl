// traversal.glsl — stackless quadtree traversal of a shadow-map region with
// min/max classification and sampled leaves (Fast PCSS).
//
// description:
//   This file: the counting every walk shares and the walks over the aligned
//   min/max mip chain (Fast PCSS's structure); traversal_pyramid.glsl walks
//   depth_pyramid.glsl's decreased pyramid (HQEPCSS) with the same rules, so a
//   call over the mip chain includes no pyramid code.
//   Seed 000 §3 (Eq. 5, 6), SPEC §4.4. For a receiver at depth dP, a texel of
//   depth d occludes when d < t, t = dP - bias (float32). The region is
//   covered by an implicit quadtree rooted at a power-of-two window; a node is
//   (level, origin) and its children are the four level-1 windows, visited in
//   Z order without a stack (a Morton code per level). Each node inside the
//   region reads its (min, max, mean) from depth_pyramid:
//     max < t    every texel occludes: add its texel count, and mean × count;
//     min >= t   none does: skip;
//     otherwise  descend — until the node's side <= the leaf side, where the
//                ambiguous leaf is estimated:
//                PN_LEAF_SAMPLED  the §3.2 samples of the sample table (4^k of
//                  them, k from the node side, set from the screen pixel):
//                  c of m samples occlude with depth sum D ->
//                  occluders += T c / m, depth sum += T D / m (T texels):
//                  Eq. 5 (blocker mean D / c) and Eq. 6 (fraction c / m) scaled to the leaf;
//                PN_LEAF_MIN      HQEPCSS: all T texels occlude at the node's min;
//                PN_LEAF_RAMP     the T texels spread evenly over [min, max]: T (t - min) / (max - min)
//                  occlude at mean depth (min + t) / 2 (a +Inf max: half of them) — no fetch.
//   Leaf side 1 is exact: a single texel is never ambiguous.
//   Regions: any rectangle, clipped to the map (the exact, non-power-of-two
//   region, SPEC §4.4 "beyond the paper"); the roots over the pyramid are in
//   traversal_pyramid.glsl's header, over the mip chain below.
//   Budget: each visited node counts; once `nodeBudget` nodes are visited no
//   node descends any more: an ambiguous node is estimated at its own level
//   (with its leaf mode; a straddling node is sampled over its part inside the
//   region). Nothing is dropped, and at most 3 nodes per level remain after
//   the budget runs out: the loop runs at most nodeBudget + 3·rootLevel + 1 times.
//   A NaN receiver depth occludes nothing and visits no node.
//   Over the aligned mip chain: traversal_mip.glsl (Fast PCSS); over the
//   decreased pyramid: traversal_pyramid.glsl (HQEPCSS). This file holds what
//   both walks share, so a call includes only its own structure's walk.
//
// use:
//   int   pnTraversalLeafSide(int leafSide, int leafDivisor, ivec2 regionSize)
//         the leaf side for a region: leafSide, or with leafDivisor > 0 at least the region's
//         longer side / leafDivisor (the leaves along a shadow edge, and so the work, stay about
//         constant as the penumbra widens)
//   int   pnTraversalRegionLeafSide(int leafSide, int leafDivisor, ivec2 regionSize)
//         the leaf side Fast PCSS walks a region with over area-weighted squares (issue 51,
//         PN_AREA_EDGES): pnTraversalLeafSide's, at most a quarter of the region's longer side
//         (rounded down to a power of two: every region is at least four leaves a side), and 1 —
//         its texels, exact — where that leaves a side under 4 (a region under 16 texels a side):
//         a leaf as wide as the region is the region estimated from one sample group (16 samples
//         for up to 256 texels: the stipple of small maps, where nearly every region is that
//         small), and a side-2 leaf's 4 samples cost its 4 texels' fetches
//   float pnTraversalBlockerMean(PnTraversal r)        depthSum / occluders (0 if none; Step 4)
//   float pnTraversalOccludedFraction(PnTraversal r)   occluders / texels, at most 1 (Step 5)
//   PnTraversal { float occluders; float depthSum; float texels; int nodes; int fetches; }
//   Counts are floats: sampled leaves add fractional counts (exact: c / m is dyadic).
//
// options:
//   PN_TRAVERSAL_MAX_LEVEL 13   largest root level (regions up to 8192 texels a side; traversal.h,
//                               shared with the runner like the leaf modes PN_LEAF_*)
//
// cost: see traversal_mip.glsl and traversal_pyramid.glsl.

#ifndef PENUMBRA_TRAVERSAL_GLSL
#define PENUMBRA_TRAVERSAL_GLSL

#include "receiver_plane.glsl"
#include "region.glsl"
#include "traversal.h"  // PN_TRAVERSAL_MAX_LEVEL, PN_LEAF_SAMPLED, PN_LEAF_MIN

// The shadow test of a traversal over the mip chain (receiver_plane.glsl): a
// texel q occludes when its depth < threshold + gradient · (q + 1/2 - centre);
// gradient 0 is one depth, threshold, for every texel.
struct PnTraversalTest {
  float threshold;  // the receiver's depth minus the bias
  vec2 gradient;    // its plane's light depth per texel (receiver_plane.glsl), or 0
  vec2 centre;      // the receiver's (u, v) in texels
};

struct PnTraversal {
  float occluders;
  float depthSum;
  float texels;
  int nodes;
  int fetches;
};

int pnTraversalLeafSide(int leafSide, int leafDivisor, ivec2 regionSize) {
  return leafDivisor > 0 ? max(leafSide, max(regionSize.x, regionSize.y) / leafDivisor) : leafSide;
}

int pnTraversalRegionLeafSide(int leafSide, int leafDivisor, ivec2 regionSize) {
  // A quarter of the longer side, rounded down to a power of two (1 for a region under 8 texels).
  int quarter = 1 << max(findMSB(max(regionSize.x, regionSize.y) / 4), 0);
  int leaf = min(pnTraversalLeafSide(leafSide, leafDivisor, regionSize), quarter);
  return leaf >= 4 ? leaf : 1;
}

// Whether a leaf mode samples the leaf (PN_LEAF_SAMPLED, PN_LEAF_QUAD), and the side whose sample
// group a sampled leaf of side `side` takes: its own, at most 4 for PN_LEAF_QUAD (traversal.h).
bool pn_traversalSamples(int leafMode) {
  return leafMode == PN_LEAF_SAMPLED || leafMode == PN_LEAF_QUAD;
}

int pn_traversalSampleSide(int leafMode, int side) {
  return leafMode == PN_LEAF_QUAD ? min(side, 4) : side;
}

float pnTraversalBlockerMean(PnTraversal r) {
  return r.occluders > 0.0 ? r.depthSum / r.occluders : 0.0;
}

float pnTraversalOccludedFraction(PnTraversal r) {
  // At most 1: area-weighted parts (PN_AREA_EDGES) sum in another order than the square's area,
  // a wholly occluded square's sum rounding a few ulps above it (visibility -1.2e-7 unclamped).
  return r.texels > 0.0 ? min(r.occluders / r.texels, 1.0) : 0.0;
}

// The even bits of v, packed: one coordinate of a Morton code.
int pn_traversalCompactBits(uint v) {
  v &= 0x55555555u;
  v = (v | (v >> 1)) & 0x33333333u;
  v = (v | (v >> 2)) & 0x0F0F0F0Fu;
  v = (v | (v >> 4)) & 0x00FF00FFu;
  v = (v | (v >> 8)) & 0x0000FFFFu;
  return int(v);
}

// An empty result for the region clipped to an n×n map (and to the largest
// root), so every read is inside: [start, end), its texels counted.
PnTraversal pn_traversalBegin(ivec2 regionOrigin, ivec2 regionSize, int n, out ivec2 start, out ivec2 end) {
  start = clamp(regionOrigin, ivec2(0), ivec2(n));
  end = clamp(regionOrigin + max(regionSize, ivec2(0)), start, min(ivec2(n), start + (1 << PN_TRAVERSAL_MAX_LEVEL)));
  ivec2 size = end - start;
  return PnTraversal(0.0, 0.0, float(size.x * size.y), 0, 0);
}

// The same for an area (region.glsl's PnArea): its cover clipped as a rectangle, its bounds into
// the clipped cover, its texels the clipped square's area — for an integer area (pnRegionAreaOfRect)
// pn_traversalBegin's count exactly.
PnTraversal pn_traversalBeginArea(inout PnArea a, int n, out ivec2 start, out ivec2 end) {
  PnTraversal r = pn_traversalBegin(a.cover.origin, a.cover.size, n, start, end);
  a.lo = clamp(a.lo, vec2(start), vec2(end));
  a.hi = clamp(a.hi, a.lo, vec2(end));
  a.cover = PnRect(start, end - start);
  r.texels = pnRegionAreaOver(a, start, end);
  return r;
}

// The part [lo, hi)'s overlap with the area: its offset from lo and its size, as floats.
void pn_traversalPartOverlap(PnArea a, ivec2 lo, ivec2 hi, out vec2 offset, out vec2 scale) {
  vec2 from = max(vec2(lo), a.lo);
  offset = from - vec2(lo);
  scale = max(min(vec2(hi), a.hi) - from, vec2(0.0));
}

// The node of Morton code `code` and side `side` below a root at `rootOrigin`.
ivec2 pn_traversalNodeOrigin(ivec2 rootOrigin, int side, uint code) {
  return rootOrigin + side * ivec2(pn_traversalCompactBits(code), pn_traversalCompactBits(code >> 1));
}

// The stackless step: into the first child (descend), or to the next node in
// Z order — the next sibling, climbing over every level whose last child this
// was. True when the climb reaches rootLevel: the traversal is done.
bool pn_traversalNext(inout int level, inout uint code, bool descend, int rootLevel) {
  if (descend) {
    level -= 1;
    code *= 4u;
    return false;
  }
  code += 1u;
  int climb = min(findLSB(code) >> 1, rootLevel - level);
  code >>= uint(2 * climb);
  level += climb;
  return level == rootLevel;
}

// The lean walks (Fast PCSS's shipped walk, HQEPCSS's blockers): a cursor of the node relative to the
// root, (x, y) at `level`. Its step: into the first child (descend), or to the next node in Z order —
// the next sibling, climbing over every level whose last child (x and y odd) this was, the trailing
// ones of x & y, with no Morton code decoded. True when the climb passes lastLevel (the level of the
// walk's top nodes): the walk is done.
bool pn_traversalCursorNext(inout ivec2 node, inout int level, bool descend, int lastLevel) {
  if (descend) {
    level -= 1;
    node *= 2;
    return false;
  }
  int climb = findLSB(~(node.x & node.y));
  level += climb;
  node >>= climb;
  node.y += node.x & 1;
  node.x ^= 1;
  return level > lastLevel;
}

// Their loop's bound: the general walk's without a budget for the largest root — the same for every
// invocation, so the count is a scalar, and never reached (a walk ends at its last node first).
#define PN_TRAVERSAL_CURSOR_STEPS (PN_TRAVERSAL_NO_BUDGET + 3 * (PN_TRAVERSAL_MAX_LEVEL + 1) + 4)

// One sample of depth d read at texel p: counted when it occludes its own
// texel's threshold.
void pn_traversalCountSample(inout float occluding, inout float depthSum, inout PnTraversal r, float d, ivec2 p,
                             PnTraversalTest test) {
  r.fetches += 1;
  if (d < pnReceiverPlaneThreshold(test.threshold, test.gradient, test.centre, p)) {
    occluding += 1.0;
    depthSum += d;
  }
}

// Eq. 5 / 6: `occluding` of m samples, with their depth sum, scaled to the
// leaf part's weight: its texels (its size as floats, multiplied: the product
// rounds once, as float(x * y) would), or its area (pnRegionAreaOver).
void pn_traversalAddSampled(inout PnTraversal r, float texels, float occluding, float depthSum, int m) {
  r.occluders += texels * occluding / float(m);
  r.depthSum += texels * depthSum / float(m);
}

// The test's threshold at the centre of the part [lo, hi): what a min or ramp
// leaf, which has no texel of its own, is estimated against.
float pn_traversalTestAtCentre(PnTraversalTest test, ivec2 lo, ivec2 hi) {
  return test.threshold + dot(test.gradient, 0.5 * vec2(lo + hi) - test.centre);
}

// PN_LEAF_MIN and PN_LEAF_RAMP over `texels` of an ambiguous leaf of depths
// (lo, hi), lo < t <= hi (traversal.h).
void pn_traversalEstimateLeaf(inout PnTraversal r, int leafMode, float lo, float hi, float texels, float t) {
  if (leafMode == PN_LEAF_MIN) {
    r.occluders += texels;
    r.depthSum += lo * texels;
    return;
  }
  float fraction = isinf(hi) ? 0.5 : clamp((t - lo) / (hi - lo), 0.0, 1.0);  // +Inf max: no ramp, half of them
  r.occluders += fraction * texels;
  r.depthSum += fraction * texels * 0.5 * (lo + min(t, hi));
}

#endif  // PENUMBRA_TRAVERSAL_GLSL
