// traversal_mip.glsl — the traversal of traversal.glsl over the aligned
// min/max mip chain (minmax_mip.glsl): Fast PCSS's structure.
//
// description:
//   traversal.glsl's rules (its header: classification, leaves, budget).
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
//   windows. A node below the chain's first level (2) is decided by its level-2
//   ancestor's (min, max), a superset (minmax_mip.glsl); level-1 nodes resolve
//   their four texels at once, from the map, as leaves read theirs. Leaf side 1
//   with the table is exact: counts equal brute force, the depth sum is exact
//   up to float rounding of the per-node sums.
//
// use:
//   PnTraversal pnTraverseRegionMip(sampler2D map, sampler2D mip, sampler2D sampleTable, int mapSize,
//       ivec2 regionOrigin, ivec2 regionSize, float receiverDepth, float bias, int leafSide, int leafMode,
//       int nodeBudget, int depthSums, ivec2 pixel)
//       over minmax_mip.glsl's chain `mip` of the map `map` (its texels: leaves, level-1 nodes);
//       depthSums: PN_DEPTH_SUMS_NONE / _TABLE / _MIDPOINT (traversal.h).
//   PnTraversal pnTraverseRegionMipPlane(... ivec2 regionSize, vec3 receiver, vec2 gradient, float bias, ...)
//       the same with a receiver plane (receiver_plane.glsl): receiver = (u, v, d), gradient = its
//       light depth per texel; texel q occludes when d(q) < d - bias + gradient · (q + 1/2 - (u, v)),
//       a node is decided against the plane's range over its part (pnReceiverPlaneThresholdRange,
//       widened by rounding), a sampled leaf's sample against its own texel's threshold, a min or
//       ramp leaf at its part's centre. Gradient 0 is pnTraverseRegionMip exactly.
//   PnTraversal pnTraverseAreaMipPlane(sampler2D map, sampler2D mip, sampler2D sampleTable, int mapSize,
//       PnArea area, vec3 receiver, vec2 gradient, float bias, int leafSide, int leafMode, int nodeBudget,
//       int depthSums, ivec2 pixel)
//       the same over an area (region.glsl's pnRegionArea: issue 51's continuous square): the walk
//       covers its texels (area.cover) and weighs each part by its overlap (pnRegionAreaOver) —
//       1 a texel inside, a fraction on the edges — a wholly occluding or wholly lit edge part
//       weighed, not descended; a sampled leaf's samples sit at their positions inside the part's
//       overlap with the square; texels = the clipped square's area. With the table's sums an
//       edge part of differing depths that occludes wholly is weighed texel by texel (descended,
//       or at a leaf sampled), since the table sums whole texels: leaf side 1 with the table is
//       exact, as for rectangles. The rectangle forms above are this over pnRegionAreaOfRect,
//       bit for bit what they were.
//   PnTraversal pnGridRegionMip(sampler2D map, sampler2D mip, sampler2D sampleTable, int mapSize,
//       ivec2 regionOrigin, ivec2 regionSize, vec3 receiver, vec2 gradient, float bias, int grid, int leafSide,
//       int leafMode, int depthSums, ivec2 pixel)
//       bounded work (Fast PCSS's `grid`): the aligned nodes of the level whose side is the
//       region's side / grid rounded up to a power of two — at most (grid + 1)² of them, 1 <= grid
//       <= PN_GRID_MAX_CELLS (traversal.h) — each read once; an ambiguous node is a leaf, sampled
//       with the table's group for min(its side, leafSide) (16: 16 samples, 4: 4, 1: 1) or estimated
//       by leafMode. The work no longer grows with the region: the leaves along a shadow edge
//       stay about 2·grid. grid >= the region's side: the nodes are texels, sampled leaves exact.
//       _TABLE reads summed_area.glsl's table of the map through PN_TRAVERSAL_SUM_TABLE (below);
//       without that define it counts as _MIDPOINT, so a shader that never asks for exact sums
//       declares no table.
//   (PnTraversal, pnTraversalLeafSide, pnTraversalBlockerMean, pnTraversalOccludedFraction: traversal.glsl)
//
// options:
//   PN_TRAVERSAL_SUM_TABLE      a usampler2D the includer declares (summed_area.glsl's table of the
//                               map) and names here before the include: PN_DEPTH_SUMS_TABLE's exact
//                               sums (undefined: none; a parameter would force every caller to bind one)
//
// cost: one fetch per node touching the region (+4 per wholly occluding
//   part with the table), nodes <= nodeBudget + 3 · (top + 1) + 8, top = ceil(log2 side).
//   The grid: (grid + 1)² nodes at most, the sample group read once (<= 16 fetches), 4^k
//   a sampled leaf.

#ifndef PENUMBRA_TRAVERSAL_MIP_GLSL
#define PENUMBRA_TRAVERSAL_MIP_GLSL

#include "minmax_mip.glsl"
#include "sample_table.glsl"
#ifdef PN_TRAVERSAL_SUM_TABLE  // only a shader that asks for the table's exact sums reads it
#include "summed_area.glsl"
#endif
#include "traversal.glsl"

// One sample of a leaf part [lo, hi) of the map at a table position in [0, 1)², placed inside the
// part's overlap (offset, scale) with the area (pn_traversalPartOverlap).
void pn_traversalSampleAt(inout float occluding, inout float depthSum, inout PnTraversal r, sampler2D map,
                          vec2 position, ivec2 lo, ivec2 hi, vec2 offset, vec2 scale, PnTraversalTest test) {
  ivec2 p = pn_sampleTexelOver(position, lo, hi, offset, scale);
  pn_traversalCountSample(occluding, depthSum, r, pnMipMapDepth(map, p), p, test);
}

// Sample i < m of a sampled leaf, its position from the table.
void pn_traversalSampleOne(inout float occluding, inout float depthSum, inout PnTraversal r, sampler2D map,
                           sampler2D sampleTable, int first, int set, int i, int m, ivec2 lo, ivec2 hi,
                           vec2 offset, vec2 scale, PnTraversalTest test) {
  if (i >= m) return;
  pn_traversalSampleAt(occluding, depthSum, r, map, pnSample(sampleTable, first + i, set), lo, hi, offset, scale,
                       test);
}

// Eq. 5 / 6 over the part [lo, hi) of an area with the samples of a node of side `side` from the
// map, at their positions inside the part's overlap with the area (offset, scale:
// pn_traversalPartOverlap), each sample against its own texel's threshold, scaled to that
// overlap's area.
void pn_traversalSampleLeafMip(inout PnTraversal r, sampler2D map, sampler2D sampleTable, ivec2 lo, ivec2 hi,
                               vec2 offset, vec2 scale, int side, PnTraversalTest test, ivec2 pixel) {
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
  pn_traversalSampleOne(occluding, depthSum, r, map, sampleTable, first, set, 0, m, lo, hi, offset, scale, test);
  if (m > 1) {
    pn_traversalSampleOne(occluding, depthSum, r, map, sampleTable, first, set, 1, m, lo, hi, offset, scale, test);
    pn_traversalSampleOne(occluding, depthSum, r, map, sampleTable, first, set, 2, m, lo, hi, offset, scale, test);
    pn_traversalSampleOne(occluding, depthSum, r, map, sampleTable, first, set, 3, m, lo, hi, offset, scale, test);
  }
  // The bound is min(m, 16), not 16 with a break at m: a loop with a constant trip count and a
  // second exit is unrolled whole by Mesa's NIR (16 copies of a sample in the GPU's code).
  for (int g = 4; g < m; g += 4) {
    pn_traversalSampleOne(occluding, depthSum, r, map, sampleTable, first, set, g, m, lo, hi, offset, scale, test);
    pn_traversalSampleOne(occluding, depthSum, r, map, sampleTable, first, set, g + 1, m, lo, hi, offset, scale, test);
    pn_traversalSampleOne(occluding, depthSum, r, map, sampleTable, first, set, g + 2, m, lo, hi, offset, scale, test);
    pn_traversalSampleOne(occluding, depthSum, r, map, sampleTable, first, set, g + 3, m, lo, hi, offset, scale, test);
  }
  pn_traversalAddSampled(r, scale.x * scale.y, occluding, depthSum, m);
}


// The clipped part [lo, hi) of a node whose every texel occludes, of weight
// `weight` (its texels, or its area: pnRegionAreaOver): that weight, and its
// depth sum as `depthSums` asks (PN_DEPTH_SUMS_*, traversal.h): the node's
// depth times the weight when min == max (every texel the same depth); else
// the summed-area table's exact sum over the part (TABLE, 4 fetches: only for
// a part of weight 1 a texel, pn_traversalClassifyPart) or the node's midpoint
// (min + max) / 2 times the weight (MIDPOINT, no table); NONE adds no depth
// (Step 5 only counts).
void pn_traversalAddOccludingPart(inout PnTraversal r, vec2 node, ivec2 lo, ivec2 hi, float weight, int depthSums) {
  r.occluders += weight;
  if (depthSums == PN_DEPTH_SUMS_NONE) return;
  if (node.x == node.y) {
    r.depthSum += node.x * weight;
#ifdef PN_TRAVERSAL_SUM_TABLE
  } else if (depthSums == PN_DEPTH_SUMS_TABLE) {
    r.depthSum += pnSummedAreaRectSum(PN_TRAVERSAL_SUM_TABLE, lo, hi - lo).sum;
    r.fetches += 4;
#endif
  } else {
    r.depthSum += 0.5 * (node.x + node.y) * weight;  // PN_DEPTH_SUMS_MIDPOINT: within (max - min) / 2 a texel
  }
}

// Reads an aligned node of the chain and counts its clipped part [lo, hi),
// of weight `weight`, when its (min, max) decide it; returns true when it is
// ambiguous, with its (min, max) in `nodeRange`.
// The test's thresholds over the part (receiver_plane.glsl): all below the
// lowest -> every texel occludes; none below the highest -> none does.
// With the table's sums, a wholly occluding part of differing depths that an
// area weighs by less than its texels is ambiguous too: the table sums whole
// texels, so its depths are weighed where they are read (texels, or samples).
bool pn_traversalClassifyPart(inout PnTraversal r, sampler2D mip, PnMipShape shape, int level, ivec2 origin,
                              ivec2 lo, ivec2 hi, float weight, PnTraversalTest test, int depthSums,
                              out vec2 nodeRange) {
  vec2 node = pn_mipFetchOf(mip, shape, level, origin >> level);
  r.nodes += 1;
  r.fetches += 1;
  nodeRange = node;
  vec2 t = pnReceiverPlaneThresholdRange(test.threshold, test.gradient, test.centre, lo, hi);
  if (node.y < t.x) {
#ifdef PN_TRAVERSAL_SUM_TABLE
    ivec2 size = hi - lo;
    if (depthSums == PN_DEPTH_SUMS_TABLE && node.x != node.y && weight != float(size.x) * float(size.y)) return true;
#endif
    pn_traversalAddOccludingPart(r, node, lo, hi, weight, depthSums);
    return false;
  }
  return node.x < t.y;
}

// A node that will not be descended: its clipped part classified, and
// estimated by the leaf mode when ambiguous (samples spread over the part's
// overlap with the area). Without samples (min, ramp) a sloped test is taken
// at the part's centre.
void pn_traversalVisitLeafPart(inout PnTraversal r, sampler2D map, sampler2D mip, PnMipShape shape,
                               sampler2D sampleTable, PnArea a, int level, ivec2 origin, ivec2 lo, ivec2 hi,
                               PnTraversalTest test, int leafMode, int depthSums, ivec2 pixel) {
  vec2 range, offset, scale;
  pn_traversalPartOverlap(a, lo, hi, offset, scale);
  float weight = scale.x * scale.y;  // pnRegionAreaOver(a, lo, hi)
  if (!pn_traversalClassifyPart(r, mip, shape, level, origin, lo, hi, weight, test, depthSums, range)) return;
  if (!pn_traversalSamples(leafMode)) {
    pn_traversalEstimateLeaf(r, leafMode, range.x, range.y, weight, pn_traversalTestAtCentre(test, lo, hi));
  } else {
    pn_traversalSampleLeafMip(r, map, sampleTable, lo, hi, offset, scale, pn_traversalSampleSide(leafMode, 1 << level),
                              test, pixel);
  }
}

// The four level-0 children (texels) of a level-1 node at `origin`, each of its weight in the
// area (0 outside it, 1 inside an integer one).
void pn_traversalVisitTexels(inout PnTraversal r, sampler2D map, ivec2 origin, PnArea a, PnTraversalTest test,
                             int depthSums) {
  // (0,0), (1,0), (0,1), (1,1) from the map; a texel past its edge is read at the edge (outside the
  // area, so of weight 0).
  ivec2 last = textureSize(map, 0) - 1;
  ivec2 far = min(origin + 1, last);
  vec4 depths = vec4(pnMipMapDepth(map, origin), pnMipMapDepth(map, ivec2(far.x, origin.y)),
                     pnMipMapDepth(map, ivec2(origin.x, far.y)), pnMipMapDepth(map, far));
  r.fetches += 4;
  r.nodes += 4;
  // Per texel (no loop, see above): its weight, the product of its column's and its row's spans
  // (region.glsl: columns 0, 1 in x, rows 0, 1 in y), where it occludes.
  vec2 x = vec2(pnRegionAreaSpan(a, origin.x, 0), pnRegionAreaSpan(a, origin.x + 1, 0));
  vec2 y = vec2(pnRegionAreaSpan(a, origin.y, 1), pnRegionAreaSpan(a, origin.y + 1, 1));
  vec4 weights = vec4(x.x * y.x, x.y * y.x, x.x * y.y, x.y * y.y);
  vec4 t = vec4(pnReceiverPlaneThreshold(test.threshold, test.gradient, test.centre, origin),
                pnReceiverPlaneThreshold(test.threshold, test.gradient, test.centre, origin + ivec2(1, 0)),
                pnReceiverPlaneThreshold(test.threshold, test.gradient, test.centre, origin + ivec2(0, 1)),
                pnReceiverPlaneThreshold(test.threshold, test.gradient, test.centre, origin + ivec2(1, 1)));
  bvec4 occludes = lessThan(depths, t);
  // One texel at a time, in Z order, as a walk at leaf side 1 adds them (Fast PCSS's one call
  // descends to the texels, pnTraversalRegionLeafSide): the same sums, bit for bit.
  for (int i = 0; i < 4; ++i) {  // constant trip count: unrolled
    if (!occludes[i]) continue;
    r.occluders += weights[i];
    if (depthSums != PN_DEPTH_SUMS_NONE) r.depthSum += weights[i] * depths[i];
  }
}


// A traversal of the mip chain one node at a time: pnTraverseRegionMipPlane is its loop, and a
// caller that traverses two regions (Fast PCSS's Steps 4 and 5) runs one loop over both, so a GPU
// compiles one copy of the body, not one a region (docs/isa.md). The walk holds only what changes
// from node to node; the test and the settings are the caller's, passed to every step (the same
// for both of Fast PCSS's regions: kept out of the loop's registers).
struct PnTraversalWalk {
  PnTraversal r;
  PnArea area;  // the region, clipped (pn_traversalBeginArea): its cover is [regionStart, regionEnd)
  ivec2 regionStart, regionEnd, rootOrigin;
  int rootLevel, level, iterations;
  uint code;
  bool done;
};

int pn_traversalBudget(int nodeBudget) {
  return clamp(nodeBudget, 1, PN_TRAVERSAL_NO_BUDGET);
}

PnTraversalWalk pn_traversalWalkBegin(PnMipShape shape, int mapSize, PnArea area, PnTraversalTest test, int budget) {
  PnTraversalWalk w;
  w.area = area;
  w.r = pn_traversalBeginArea(w.area, clamp(mapSize, 0, shape.rows), w.regionStart, w.regionEnd);
  ivec2 size = w.regionEnd - w.regionStart;
  w.done = isnan(test.threshold) || size.x == 0 || size.y == 0;
  // The 2×2 aligned nodes of level `top` at the region's aligned corner cover
  // it (side <= 2^top); they are the children of a virtual root one level up,
  // which is never read: the walk starts at its first child.
  int top = min(findMSB(max(size.x, size.y) - 1) + 1, shape.top);
  w.rootLevel = top + 1;
  w.rootOrigin = (w.regionStart >> top) << top;
  w.level = top;
  w.code = 0u;
  // One node a step (four texels at level 1): the budget's nodes, then no node descends and at most
  // the 3 later siblings of each node on the path remain, one a level from `top` down to 1 (a side-2
  // node's texels are read in its own step). Tight: a walk that spends its budget on the way down to
  // its first level-1 node takes every iteration (the traversal check's budget-8 case).
  w.iterations = w.done ? 0 : budget + 3 * top;
  return w;
}

// The walk's next node (none once done). budget: pn_traversalBudget's.
void pn_traversalWalkStep(inout PnTraversalWalk w, sampler2D map, sampler2D mip, PnMipShape shape,
                          sampler2D sampleTable, PnTraversalTest test, int leafSide, int leafMode, int budget,
                          int depthSums, ivec2 pixel) {
  if (w.done) return;
  int side = 1 << w.level;
  ivec2 origin = pn_traversalNodeOrigin(w.rootOrigin, side, w.code);
  ivec2 lo = max(origin, w.regionStart);
  ivec2 hi = min(origin + side, w.regionEnd);
  bool descend = false;
  if (all(lessThan(lo, hi))) {
    bool spent = w.r.nodes + 1 >= budget;
    if (side <= leafSide || spent) {
      pn_traversalVisitLeafPart(w.r, map, mip, shape, sampleTable, w.area, w.level, origin, lo, hi, test, leafMode,
                                depthSums, pixel);
    } else {
      vec2 range;
      if (pn_traversalClassifyPart(w.r, mip, shape, w.level, origin, lo, hi, pnRegionAreaOver(w.area, lo, hi), test,
                                   depthSums, range)) {
        if (side == 2) {
          // Texels: never ambiguous, so classified here, four at a time and
          // without a sampling loop: with leaf children visited inline (as
          // pnTraverseRegion does) llvmpipe's loop cut-off of 65535
          // iterations per invocation ended the exact (leaf 1) traversal of
          // a 256² fine checker early; one sampling site a step does not.
          pn_traversalVisitTexels(w.r, map, origin, w.area, test, depthSums);
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

PnTraversal pnTraverseAreaMipPlane(sampler2D map, sampler2D mip, sampler2D sampleTable, int mapSize, PnArea area,
                                   vec3 receiver, vec2 gradient, float bias, int leafSide, int leafMode,
                                   int nodeBudget, int depthSums, ivec2 pixel) {
  PnMipShape shape = pn_mipShape(mip);
  PnTraversalTest test = PnTraversalTest(receiver.z - bias, gradient, receiver.xy);
  int budget = pn_traversalBudget(nodeBudget);
  PnTraversalWalk w = pn_traversalWalkBegin(shape, mapSize, area, test, budget);
  for (int it = 0; it < w.iterations; ++it) {
    if (w.done) break;
    pn_traversalWalkStep(w, map, mip, shape, sampleTable, test, leafSide, leafMode, budget, depthSums, pixel);
  }
  return w.r;
}

PnTraversal pnTraverseRegionMipPlane(sampler2D map, sampler2D mip, sampler2D sampleTable, int mapSize,
                                     ivec2 regionOrigin, ivec2 regionSize, vec3 receiver, vec2 gradient, float bias,
                                     int leafSide, int leafMode, int nodeBudget, int depthSums, ivec2 pixel) {
  return pnTraverseAreaMipPlane(map, mip, sampleTable, mapSize, pnRegionAreaOfRect(PnRect(regionOrigin, regionSize)),
                                receiver, gradient, bias, leafSide, leafMode, nodeBudget, depthSums, pixel);
}

// The same region counted with bounded work: the aligned nodes of the level
// whose side is the region's side / grid (rounded up to a power of two), each
// read once and decided against the test; an ambiguous one is a leaf, never
// descended — sampled from the table's group for min(its side, leafSide), or
// estimated by the leaf mode. At most (grid + 1)² nodes whatever the region's
// size; with grid >= the region's side the nodes are texels: exact.
PnTraversal pn_gridAreaMip(sampler2D map, sampler2D mip, sampler2D sampleTable, int mapSize, PnArea area,
                           vec3 receiver, vec2 gradient, float bias, int grid, int leafSide, int leafMode,
                           int depthSums, ivec2 pixel) {
  PnMipShape shape = pn_mipShape(mip);
  ivec2 start, end;
  PnTraversal r = pn_traversalBeginArea(area, clamp(mapSize, 0, shape.rows), start, end);
  ivec2 size = end - start;
  PnTraversalTest test = PnTraversalTest(receiver.z - bias, gradient, receiver.xy);
  if (isnan(test.threshold) || size.x == 0 || size.y == 0) return r;
  int cells = clamp(grid, 1, PN_GRID_MAX_CELLS);
  int cell = max(1, (max(size.x, size.y) + cells - 1) / cells);
  int level = min(findMSB(cell - 1) + 1, shape.top);  // ceil(log2 cell)
  int side = 1 << level;
  ivec2 first = start >> level;
  ivec2 count = ((end - 1) >> level) - first + 1;  // <= cells + 1 a side
  // One sample group for every leaf (the pixel's set of the group for
  // min(side, leafSide)): its positions read once, not once a leaf.
  int k = pnSampleGroupLog4(pn_traversalSampleSide(leafMode, min(side, max(leafSide, 1))));
  int m = pnSampleCount(k);
  vec2 positions[PN_SAMPLE_MAX_COUNT];
  if (pn_traversalSamples(leafMode)) {
    int firstColumn = pnSampleFirstColumn(k), set = pnSampleSet(pixel);
    for (int i = 0; i < PN_SAMPLE_MAX_COUNT; ++i) positions[i] = i < m ? pnSample(sampleTable, firstColumn + i, set) : vec2(0.0);
  }
  for (int j = 0; j <= PN_GRID_MAX_CELLS; ++j) {
    if (j >= count.y) break;
    for (int i = 0; i <= PN_GRID_MAX_CELLS; ++i) {
      if (i >= count.x) break;
      ivec2 origin = (first + ivec2(i, j)) << level;
      ivec2 lo = max(origin, start), hi = min(origin + side, end);
      vec2 offset, scale;
      pn_traversalPartOverlap(area, lo, hi, offset, scale);
      float weight = scale.x * scale.y;  // pnRegionAreaOver(area, lo, hi)
      vec2 range;
      if (!pn_traversalClassifyPart(r, mip, shape, level, origin, lo, hi, weight, test, depthSums, range)) continue;
      if (!pn_traversalSamples(leafMode)) {
        pn_traversalEstimateLeaf(r, leafMode, range.x, range.y, weight, pn_traversalTestAtCentre(test, lo, hi));
      } else {
        float occluding = 0.0, depthSum = 0.0;
        for (int g = 0; g < PN_SAMPLE_MAX_COUNT; g += 4) {
          if (g >= m) break;
          for (int i = g; i < g + 4; ++i) {  // constant trip count: unrolled
            if (i < m) pn_traversalSampleAt(occluding, depthSum, r, map, positions[i], lo, hi, offset, scale, test);
          }
        }
        pn_traversalAddSampled(r, weight, occluding, depthSum, m);
      }
    }
  }
  return r;
}

PnTraversal pnGridRegionMip(sampler2D map, sampler2D mip, sampler2D sampleTable, int mapSize, ivec2 regionOrigin,
                            ivec2 regionSize, vec3 receiver, vec2 gradient, float bias, int grid, int leafSide,
                            int leafMode, int depthSums, ivec2 pixel) {
  return pn_gridAreaMip(map, mip, sampleTable, mapSize, pnRegionAreaOfRect(PnRect(regionOrigin, regionSize)), receiver,
                        gradient, bias, grid, leafSide, leafMode, depthSums, pixel);
}

PnTraversal pnTraverseRegionMip(sampler2D map, sampler2D mip, sampler2D sampleTable, int mapSize,
                                ivec2 regionOrigin, ivec2 regionSize, float receiverDepth, float bias, int leafSide,
                                int leafMode, int nodeBudget, int depthSums, ivec2 pixel) {
  return pnTraverseRegionMipPlane(map, mip, sampleTable, mapSize, regionOrigin, regionSize,
                                  vec3(0.0, 0.0, receiverDepth), vec2(0.0), bias, leafSide, leafMode, nodeBudget,
                                  depthSums, pixel);
}

#endif  // PENUMBRA_TRAVERSAL_MIP_GLSL
