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
//   Over the aligned mip chain (pnTraverseRegionMip, minmax_mip.glsl): the
//   roots are the 2×2 aligned nodes of level ceil(log2 side) at the region's
//   aligned corner; every node that touches the region is read and its part
//   inside the region [lo, hi) counted when its (min, max) decide it: none
//   occludes -> skip; all occlude -> the part's texels, and its depth sum
//   (depthSums: the summed-area table's exact sum over the part, or the node's
//   midpoint times the part's texels, or none for Step 5's counts); an
//   ambiguous node descends, or at a leaf is estimated over its part (samples
//   spread over the part). So a straddling node costs one fetch (plus 4 for
//   the table), not a descent to the border: exact regions at the cost of
//   windows. Level-1 nodes resolve their four texels at once. Leaf side 1 with
//   the table is exact: counts equal brute force, the depth sum is exact up to
//   float rounding of the per-node sums.
//
// use:
//   PnTraversal pnTraverseRegionMip(sampler2D mip, sampler2D sampleTable, int mapSize,
//       ivec2 regionOrigin, ivec2 regionSize, float receiverDepth, float bias, int leafSide, int leafMode,
//       int nodeBudget, int depthSums, ivec2 pixel)
//       over minmax_mip.glsl's chain; depthSums: PN_DEPTH_SUMS_NONE / _TABLE / _MIDPOINT (traversal.h).
//   PnTraversal pnTraverseRegionMipPlane(... ivec2 regionSize, vec3 receiver, vec2 gradient, float bias, ...)
//       the same with a receiver plane (receiver_plane.glsl): receiver = (u, v, d), gradient = its
//       light depth per texel; texel q occludes when d(q) < d - bias + gradient · (q + 1/2 - (u, v)),
//       a node is decided against the plane's range over its part (pnReceiverPlaneThresholdRange,
//       widened by rounding), a sampled leaf's sample against its own texel's threshold, a min or
//       ramp leaf at its part's centre. Gradient 0 is pnTraverseRegionMip exactly.
//   PnTraversal pnGridRegionMip(sampler2D mip, sampler2D sampleTable, int mapSize, ivec2 regionOrigin,
//       ivec2 regionSize, vec3 receiver, vec2 gradient, float bias, int grid, int leafSide, int leafMode,
//       int depthSums, ivec2 pixel)
//       bounded work (Fast PCSS's `grid`): the aligned nodes of the level whose side is the
//       region's side / grid rounded up to a power of two — at most (grid + 1)² of them, 1 <= grid
//       <= PN_GRID_MAX_CELLS (traversal.h) — each read once; an ambiguous node is a leaf, sampled
//       with the table's group for min(its side, leafSide) (16: 16 samples, 4: 4, 1: 1) or estimated
//       by leafMode. The work no longer grows with the region: the leaves along a shadow edge
//       stay about 2·grid. grid >= the region's side: the nodes are texels, exact.
//       _TABLE reads summed_area.glsl's table of the map through PN_TRAVERSAL_SUM_TABLE (below);
//       without that define it counts as _MIDPOINT, so a shader that never asks for exact sums
//       declares no table.
//   int   pnTraversalLeafSide(int leafSide, int leafDivisor, ivec2 regionSize)
//         the leaf side for a region: leafSide, or with leafDivisor > 0 at least the region's
//         longer side / leafDivisor (the leaves along a shadow edge, and so the work, stay about
//         constant as the penumbra widens)
//   float pnTraversalBlockerMean(PnTraversal r)        depthSum / occluders (0 if none; Step 4)
//   float pnTraversalOccludedFraction(PnTraversal r)   occluders / texels (Step 5)
//   PnTraversal { float occluders; float depthSum; float texels; int nodes; int fetches; }
//   Counts are floats: sampled leaves add fractional counts (exact: c / m is dyadic).
//
// options:
//   PN_TRAVERSAL_SUM_TABLE      a usampler2D the includer declares (summed_area.glsl's table of the
//                               map) and names here before the include: PN_DEPTH_SUMS_TABLE's exact
//                               sums (undefined: none; a parameter would force every caller to bind one)
//   PN_TRAVERSAL_MAX_LEVEL 13   largest root level (regions up to 8192 texels a side; traversal.h,
//                               shared with the runner like the leaf modes PN_LEAF_*)
//
// cost: one fetch per node inside the region, 4^k <= 16 per sampled leaf;
//   nodes <= min(4/3 · side², nodeBudget + 3 · rootLevel + 1). Over the mip
//   chain: one fetch per node touching the region (+4 per wholly occluding
//   part with the table), nodes <= nodeBudget + 3 · (top + 1) + 8, top = ceil(log2 side).
//   The grid: (grid + 1)² nodes at most, the sample group read once (<= 16 fetches), 4^k
//   a sampled leaf.

#ifndef PENUMBRA_TRAVERSAL_GLSL
#define PENUMBRA_TRAVERSAL_GLSL

#include "minmax_mip.glsl"
#include "sample_table.glsl"
#include "receiver_plane.glsl"
#ifdef PN_TRAVERSAL_SUM_TABLE  // only a shader that asks for the table's exact sums reads it
#include "summed_area.glsl"
#endif
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

float pnTraversalBlockerMean(PnTraversal r) {
  return r.occluders > 0.0 ? r.depthSum / r.occluders : 0.0;
}

float pnTraversalOccludedFraction(PnTraversal r) {
  return r.texels > 0.0 ? r.occluders / r.texels : 0.0;
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
// leaf's texels.
void pn_traversalAddSampled(inout PnTraversal r, ivec2 size, float occluding, float depthSum, int m) {
  float texels = float(size.x * size.y);
  r.occluders += texels * occluding / float(m);
  r.depthSum += texels * depthSum / float(m);
}

// One sample of a leaf [lo, lo + size) over the mip chain's level 0, at a
// table position in [0, 1)².
void pn_traversalSampleAt(inout float occluding, inout float depthSum, inout PnTraversal r, sampler2D mip,
                          PnMipShape shape, vec2 position, ivec2 lo, ivec2 size, PnTraversalTest test) {
  ivec2 p = pnSampleTexel(position, lo, size);
  pn_traversalCountSample(occluding, depthSum, r, pn_mipFetchOf(mip, shape, 0, p).x, p, test);
}

// Sample i < m of a sampled leaf, its position from the table.
void pn_traversalSampleOne(inout float occluding, inout float depthSum, inout PnTraversal r, sampler2D mip,
                           PnMipShape shape, sampler2D sampleTable, int first, int set, int i, int m, ivec2 lo,
                           ivec2 size, PnTraversalTest test) {
  if (i >= m) return;
  pn_traversalSampleAt(occluding, depthSum, r, mip, shape, pnSample(sampleTable, first + i, set), lo, size, test);
}

// Eq. 5 / 6 over the rectangle [lo, lo + size) with the samples of a node of
// side `side` over the mip chain's level 0, each sample against its own
// texel's threshold.
void pn_traversalSampleLeafMip(inout PnTraversal r, sampler2D mip, PnMipShape shape, sampler2D sampleTable, ivec2 lo,
                           ivec2 size, int side, PnTraversalTest test, ivec2 pixel) {
  int k = pnSampleGroupLog4(side);
  int m = pnSampleCount(k);
  int first = pnSampleFirstColumn(k);
  int set = pnSampleSet(pixel);
  float occluding = 0.0;
  float depthSum = 0.0;
  // m is 1, 4 or 16. llvmpipe ends a loop once its iterations, summed over
  // all its entries in one invocation, reach 65535 (measured: a 256² fine
  // checker at leaf 2 hits it one sample a step, and at four a step once the
  // plane's threshold made the loop too long to unroll): the first four
  // samples are taken without a loop, the rest (16-sample leaves, at most a
  // sixteenth of the region's texels) four a step.
  pn_traversalSampleOne(occluding, depthSum, r, mip, shape, sampleTable, first, set, 0, m, lo, size, test);
  if (m > 1) {
    pn_traversalSampleOne(occluding, depthSum, r, mip, shape, sampleTable, first, set, 1, m, lo, size, test);
    pn_traversalSampleOne(occluding, depthSum, r, mip, shape, sampleTable, first, set, 2, m, lo, size, test);
    pn_traversalSampleOne(occluding, depthSum, r, mip, shape, sampleTable, first, set, 3, m, lo, size, test);
  }
  // The bound is min(m, 16), not 16 with a break at m: a loop with a constant trip count and a
  // second exit is unrolled whole by Mesa's NIR (16 copies of a sample in the GPU's code).
  for (int g = 4; g < m; g += 4) {
    pn_traversalSampleOne(occluding, depthSum, r, mip, shape, sampleTable, first, set, g, m, lo, size, test);
    pn_traversalSampleOne(occluding, depthSum, r, mip, shape, sampleTable, first, set, g + 1, m, lo, size, test);
    pn_traversalSampleOne(occluding, depthSum, r, mip, shape, sampleTable, first, set, g + 2, m, lo, size, test);
    pn_traversalSampleOne(occluding, depthSum, r, mip, shape, sampleTable, first, set, g + 3, m, lo, size, test);
  }
  pn_traversalAddSampled(r, size, occluding, depthSum, m);
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

// ---- Over the aligned min/max mip chain (minmax_mip.glsl) -------------------

// The clipped part [lo, hi) of a node whose every texel occludes: its texels,
// and their depth sum as `depthSums` asks (PN_DEPTH_SUMS_*, traversal.h): the
// node's depth times its texels when min == max (every texel the same depth:
// level 0 always); else the summed-area table's exact sum over the part
// (TABLE, 4 fetches) or the node's midpoint (min + max) / 2 times its texels
// (MIDPOINT, no table); NONE adds no depth (Step 5 only counts).
void pn_traversalAddOccludingPart(inout PnTraversal r, vec2 node, ivec2 lo, ivec2 hi,
                                  int depthSums) {
  ivec2 size = hi - lo;
  float texels = float(size.x * size.y);
  r.occluders += texels;
  if (depthSums == PN_DEPTH_SUMS_NONE) return;
  if (node.x == node.y) {
    r.depthSum += node.x * texels;
#ifdef PN_TRAVERSAL_SUM_TABLE
  } else if (depthSums == PN_DEPTH_SUMS_TABLE) {
    r.depthSum += pnSummedAreaRectSum(PN_TRAVERSAL_SUM_TABLE, lo, size).sum;
    r.fetches += 4;
#endif
  } else {
    r.depthSum += 0.5 * (node.x + node.y) * texels;  // PN_DEPTH_SUMS_MIDPOINT: within (max - min) / 2 a texel
  }
}

// Reads an aligned node of the chain and counts its clipped part [lo, hi)
// when its (min, max) decide it; returns true when it is ambiguous, with its
// (min, max) in `nodeRange`.
// The test's thresholds over the part (receiver_plane.glsl): all below the
// lowest -> every texel occludes; none below the highest -> none does.
bool pn_traversalClassifyPart(inout PnTraversal r, sampler2D mip, PnMipShape shape, int level, ivec2 origin,
                              ivec2 lo, ivec2 hi, PnTraversalTest test, int depthSums, out vec2 nodeRange) {
  vec2 node = pn_mipFetchOf(mip, shape, level, origin >> level);
  r.nodes += 1;
  r.fetches += 1;
  nodeRange = node;
  vec2 t = pnReceiverPlaneThresholdRange(test.threshold, test.gradient, test.centre, lo, hi);
  if (node.y < t.x) {
    pn_traversalAddOccludingPart(r, node, lo, hi, depthSums);
    return false;
  }
  return node.x < t.y;
}

// A node that will not be descended: its clipped part classified, and
// estimated by the leaf mode when ambiguous (samples spread over the part).
// Without samples (min, ramp) a sloped test is taken at the part's centre.
void pn_traversalVisitLeafPart(inout PnTraversal r, sampler2D mip, PnMipShape shape, sampler2D sampleTable,
                               int level, ivec2 origin, ivec2 lo, ivec2 hi, PnTraversalTest test, int leafMode,
                               int depthSums, ivec2 pixel) {
  vec2 range;
  if (!pn_traversalClassifyPart(r, mip, shape, level, origin, lo, hi, test, depthSums, range)) return;
  if (leafMode != PN_LEAF_SAMPLED) {
    ivec2 size = hi - lo;
    pn_traversalEstimateLeaf(r, leafMode, range.x, range.y, float(size.x * size.y), pn_traversalTestAtCentre(test, lo, hi));
  } else {
    pn_traversalSampleLeafMip(r, mip, shape, sampleTable, lo, hi - lo, 1 << level, test, pixel);
  }
}

// The four level-0 children (texels) of a level-1 node at `origin`, clipped to the region.
void pn_traversalVisitTexels(inout PnTraversal r, sampler2D mip, PnMipShape shape, ivec2 origin,
                             ivec2 regionStart, ivec2 regionEnd, PnTraversalTest test, int depthSums) {
  vec4 pair0 = pn_mipTexelOf(mip, shape, 0, ivec2(origin.x >> 1, origin.y));
  vec4 pair1 = pn_mipTexelOf(mip, shape, 0, ivec2(origin.x >> 1, origin.y + 1));
  vec4 depths = vec4(pair0.x, pair0.z, pair1.x, pair1.z);  // (0,0), (1,0), (0,1), (1,1): min = max = depth
  r.fetches += 2;
  r.nodes += 4;
  // Per texel: inside the region and occluding (no loop, see above).
  bvec2 lower = greaterThanEqual(origin, regionStart), upper = lessThan(origin + ivec2(1), regionEnd);
  bvec2 first = lessThan(origin, regionEnd), second = greaterThanEqual(origin + ivec2(1), regionStart);
  bvec2 x = bvec2(lower.x && first.x, second.x && upper.x);  // columns 0, 1 inside
  bvec2 y = bvec2(lower.y && first.y, second.y && upper.y);  // rows 0, 1 inside
  vec4 inside = vec4(x.x && y.x, x.y && y.x, x.x && y.y, x.y && y.y);
  vec4 t = vec4(pnReceiverPlaneThreshold(test.threshold, test.gradient, test.centre, origin),
                pnReceiverPlaneThreshold(test.threshold, test.gradient, test.centre, origin + ivec2(1, 0)),
                pnReceiverPlaneThreshold(test.threshold, test.gradient, test.centre, origin + ivec2(0, 1)),
                pnReceiverPlaneThreshold(test.threshold, test.gradient, test.centre, origin + ivec2(1, 1)));
  vec4 occluding = inside * vec4(lessThan(depths, t));
  r.occluders += dot(occluding, vec4(1.0));
  if (depthSums != PN_DEPTH_SUMS_NONE) r.depthSum += dot(occluding, mix(vec4(0.0), depths, greaterThan(occluding, vec4(0.0))));
}

// A traversal of the mip chain one node at a time: pnTraverseRegionMipPlane is its loop, and a
// caller that traverses two regions (Fast PCSS's Steps 4 and 5) runs one loop over both, so a GPU
// compiles one copy of the body, not one a region (docs/isa.md). The walk holds only what changes
// from node to node; the test and the settings are the caller's, passed to every step (the same
// for both of Fast PCSS's regions: kept out of the loop's registers).
struct PnTraversalWalk {
  PnTraversal r;
  ivec2 regionStart, regionEnd, rootOrigin;
  int rootLevel, level, iterations;
  uint code;
  bool done;
};

int pn_traversalBudget(int nodeBudget) {
  return clamp(nodeBudget, 1, PN_TRAVERSAL_NO_BUDGET);
}

PnTraversalWalk pn_traversalWalkBegin(PnMipShape shape, int mapSize, ivec2 regionOrigin, ivec2 regionSize,
                                      PnTraversalTest test, int budget) {
  PnTraversalWalk w;
  w.r = pn_traversalBegin(regionOrigin, regionSize, clamp(mapSize, 0, shape.rows), w.regionStart, w.regionEnd);
  ivec2 size = w.regionEnd - w.regionStart;
  w.done = isnan(test.threshold) || w.r.texels == 0.0;
  // The 2×2 aligned nodes of level `top` at the region's aligned corner cover
  // it (side <= 2^top); they are the children of a virtual root one level up,
  // which is never read: the walk starts at its first child.
  int top = min(findMSB(max(size.x, size.y) - 1) + 1, shape.top);
  w.rootLevel = top + 1;
  w.rootOrigin = (w.regionStart >> top) << top;
  w.level = top;
  w.code = 0u;
  // One node a step (four texels at level 1); once the budget is spent no node
  // descends, and at most 3 siblings a level remain.
  w.iterations = w.done ? 0 : budget + 3 * w.rootLevel + 4;
  return w;
}

// The walk's next node (none once done). budget: pn_traversalBudget's.
void pn_traversalWalkStep(inout PnTraversalWalk w, sampler2D mip, PnMipShape shape, sampler2D sampleTable,
                          PnTraversalTest test, int leafSide, int leafMode, int budget, int depthSums, ivec2 pixel) {
  if (w.done) return;
  int side = 1 << w.level;
  ivec2 origin = pn_traversalNodeOrigin(w.rootOrigin, side, w.code);
  ivec2 lo = max(origin, w.regionStart);
  ivec2 hi = min(origin + side, w.regionEnd);
  bool descend = false;
  if (all(lessThan(lo, hi))) {
    bool spent = w.r.nodes + 1 >= budget;
    if (side <= leafSide || spent) {
      pn_traversalVisitLeafPart(w.r, mip, shape, sampleTable, w.level, origin, lo, hi, test, leafMode, depthSums, pixel);
    } else {
      vec2 range;
      if (pn_traversalClassifyPart(w.r, mip, shape, w.level, origin, lo, hi, test, depthSums, range)) {
        if (side == 2) {
          // Texels: never ambiguous, so classified here, four at a time and
          // without a sampling loop: with leaf children visited inline (as
          // pnTraverseRegion does) llvmpipe's loop cut-off of 65535
          // iterations per invocation ended the exact (leaf 1) traversal of
          // a 256² fine checker early; one sampling site a step does not.
          pn_traversalVisitTexels(w.r, mip, shape, origin, w.regionStart, w.regionEnd, test, depthSums);
        } else {
          descend = true;
        }
      }
    }
  } else {
    w.r.nodes += 1;  // outside the region: visited, nothing to read
  }
  // The virtual root's four children done: the walk is over.
  w.done = pn_traversalNext(w.level, w.code, descend, w.rootLevel);
}

PnTraversal pnTraverseRegionMipPlane(sampler2D mip, sampler2D sampleTable, int mapSize,
                                     ivec2 regionOrigin, ivec2 regionSize, vec3 receiver, vec2 gradient, float bias,
                                     int leafSide, int leafMode, int nodeBudget, int depthSums, ivec2 pixel) {
  PnMipShape shape = pn_mipShape(mip);
  PnTraversalTest test = PnTraversalTest(receiver.z - bias, gradient, receiver.xy);
  int budget = pn_traversalBudget(nodeBudget);
  PnTraversalWalk w = pn_traversalWalkBegin(shape, mapSize, regionOrigin, regionSize, test, budget);
  for (int it = 0; it < w.iterations; ++it) {
    if (w.done) break;
    pn_traversalWalkStep(w, mip, shape, sampleTable, test, leafSide, leafMode, budget, depthSums, pixel);
  }
  return w.r;
}

// The same region counted with bounded work: the aligned nodes of the level
// whose side is the region's side / grid (rounded up to a power of two), each
// read once and decided against the test; an ambiguous one is a leaf, never
// descended — sampled from the table's group for min(its side, leafSide), or
// estimated by the leaf mode. At most (grid + 1)² nodes whatever the region's
// size; with grid >= the region's side the nodes are texels: exact.
PnTraversal pnGridRegionMip(sampler2D mip, sampler2D sampleTable, int mapSize, ivec2 regionOrigin,
                            ivec2 regionSize, vec3 receiver, vec2 gradient, float bias, int grid, int leafSide,
                            int leafMode, int depthSums, ivec2 pixel) {
  PnMipShape shape = pn_mipShape(mip);
  ivec2 start, end;
  PnTraversal r = pn_traversalBegin(regionOrigin, regionSize, clamp(mapSize, 0, shape.rows), start, end);
  ivec2 size = end - start;
  PnTraversalTest test = PnTraversalTest(receiver.z - bias, gradient, receiver.xy);
  if (isnan(test.threshold) || r.texels == 0.0) return r;
  int cells = clamp(grid, 1, PN_GRID_MAX_CELLS);
  int cell = max(1, (max(size.x, size.y) + cells - 1) / cells);
  int level = min(findMSB(cell - 1) + 1, shape.top);  // ceil(log2 cell)
  int side = 1 << level;
  ivec2 first = start >> level;
  ivec2 count = ((end - 1) >> level) - first + 1;  // <= cells + 1 a side
  // One sample group for every leaf (the pixel's set of the group for
  // min(side, leafSide)): its positions read once, not once a leaf.
  int k = pnSampleGroupLog4(min(side, max(leafSide, 1)));
  int m = pnSampleCount(k);
  vec2 positions[PN_SAMPLE_MAX_COUNT];
  if (leafMode == PN_LEAF_SAMPLED) {
    int firstColumn = pnSampleFirstColumn(k), set = pnSampleSet(pixel);
    for (int i = 0; i < PN_SAMPLE_MAX_COUNT; ++i) positions[i] = i < m ? pnSample(sampleTable, firstColumn + i, set) : vec2(0.0);
  }
  for (int j = 0; j <= PN_GRID_MAX_CELLS; ++j) {
    if (j >= count.y) break;
    for (int i = 0; i <= PN_GRID_MAX_CELLS; ++i) {
      if (i >= count.x) break;
      ivec2 origin = (first + ivec2(i, j)) << level;
      ivec2 lo = max(origin, start), hi = min(origin + side, end);
      vec2 range;
      if (!pn_traversalClassifyPart(r, mip, shape, level, origin, lo, hi, test, depthSums, range)) continue;
      if (leafMode != PN_LEAF_SAMPLED) {
        pn_traversalEstimateLeaf(r, leafMode, range.x, range.y, float((hi.x - lo.x) * (hi.y - lo.y)),
                                 pn_traversalTestAtCentre(test, lo, hi));
      } else {
        float occluding = 0.0, depthSum = 0.0;
        for (int g = 0; g < PN_SAMPLE_MAX_COUNT; g += 4) {
          if (g >= m) break;
          for (int i = g; i < g + 4; ++i) {  // constant trip count: unrolled
            if (i < m) pn_traversalSampleAt(occluding, depthSum, r, mip, shape, positions[i], lo, hi - lo, test);
          }
        }
        pn_traversalAddSampled(r, hi - lo, occluding, depthSum, m);
      }
    }
  }
  return r;
}

PnTraversal pnTraverseRegionMip(sampler2D mip, sampler2D sampleTable, int mapSize,
                                ivec2 regionOrigin, ivec2 regionSize, float receiverDepth, float bias, int leafSide,
                                int leafMode, int nodeBudget, int depthSums, ivec2 pixel) {
  return pnTraverseRegionMipPlane(mip, sampleTable, mapSize, regionOrigin, regionSize, vec3(0.0, 0.0, receiverDepth),
                                  vec2(0.0), bias, leafSide, leafMode, nodeBudget, depthSums, pixel);
}

#endif  // PENUMBRA_TRAVERSAL_GLSL
