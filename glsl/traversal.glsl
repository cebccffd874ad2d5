// traversal.glsl — stackless quadtree traversal of a shadow-map region with
// min/max classification and sampled leaves (Fast PCSS).
//
// description:
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
//                PN_LEAF_MIN      HQEPCSS: all T texels occlude at the node's min.
//   Leaf side 1 is exact: a single texel is never ambiguous.
//   Regions: pnTraverseRegion takes any rectangle, clipped to the map (the exact,
//   non-power-of-two region, SPEC §4.4 "beyond the paper"); its root is the
//   smallest power-of-two square at the region's origin that covers it. Nodes
//   outside the region are skipped, nodes straddling its border (or above the
//   pyramid's last level) are descended, never read. For the paper's power-of-
//   two window (region.glsl) the region is the window and the root itself.
//   Budget: each visited node counts; once `nodeBudget` nodes are visited no
//   node descends any more: an ambiguous node is estimated at its own level
//   (with its leaf mode; a straddling node is sampled over its part inside the
//   region). Nothing is dropped, and at most 3 nodes per level remain after
//   the budget runs out: the loop runs at most nodeBudget + 3·rootLevel + 1 times.
//   A NaN receiver depth occludes nothing and visits no node.
//
// use:
//   PnTraversal pnTraverseRegion(sampler2DArray pyramid, sampler2D sampleTable,
//       ivec2 regionOrigin, ivec2 regionSize, float receiverDepth, float bias,
//       int leafSide, int leafMode, int nodeBudget, ivec2 pixel)
//   PnTraversal pnTraverseWindow(... PnWindow window ...)       the region.glsl window
//   float pnTraversalBlockerMean(PnTraversal r)        depthSum / occluders (0 if none; Step 4)
//   float pnTraversalOccludedFraction(PnTraversal r)   occluders / texels (Step 5)
//   PnTraversal { float occluders; float depthSum; float texels; int nodes; int fetches; }
//   Counts are floats: sampled leaves add fractional counts (exact: c / m is dyadic).
//
// options:
//   PN_TRAVERSAL_MAX_LEVEL 13   largest root level (regions up to 8192 texels a side; traversal.h,
//                               shared with the runner like the leaf modes PN_LEAF_*)
//
// cost: one fetch per node inside the region, 4^k <= 16 per sampled leaf;
//   nodes <= min(4/3 · side², nodeBudget + 3 · rootLevel + 1).

#ifndef PENUMBRA_TRAVERSAL_GLSL
#define PENUMBRA_TRAVERSAL_GLSL

#include "depth_pyramid.glsl"
#include "region.glsl"
#include "sample_table.glsl"
#include "traversal.h"  // PN_TRAVERSAL_MAX_LEVEL, PN_LEAF_SAMPLED, PN_LEAF_MIN

struct PnTraversal {
  float occluders;
  float depthSum;
  float texels;
  int nodes;
  int fetches;
};

float pnTraversalBlockerMean(PnTraversal r) {
  return r.occluders > 0.0 ? r.depthSum / r.occluders : 0.0;
}

float pnTraversalOccludedFraction(PnTraversal r) {
  return r.texels > 0.0 ? r.occluders / r.texels : 0.0;
}

// The even bits of v, packed: one coordinate of a Morton code.
int pnTraversalCompactBits(uint v) {
  v &= 0x55555555u;
  v = (v | (v >> 1)) & 0x33333333u;
  v = (v | (v >> 2)) & 0x0F0F0F0Fu;
  v = (v | (v >> 4)) & 0x00FF00FFu;
  v = (v | (v >> 8)) & 0x0000FFFFu;
  return int(v);
}

// Eq. 5 / 6 over the rectangle [lo, lo + size) with the samples of a node of side `side`.
void pnTraversalSampleLeaf(inout PnTraversal r, sampler2DArray pyramid, sampler2D sampleTable, ivec2 lo,
                           ivec2 size, int side, float t, ivec2 pixel) {
  int k = pnSampleGroupLog4(side);
  int m = pnSampleCount(k);
  int first = pnSampleFirstColumn(k);
  int set = pnSampleSet(pixel);
  float occluding = 0.0;
  float depthSum = 0.0;
  for (int i = 0; i < PN_SAMPLE_MAX_COUNT; ++i) {
    if (i >= m) break;
    ivec2 p = pnSampleTexel(pnSample(sampleTable, first + i, set), lo, size);
    float d = pnPyramidFetch(pyramid, 0, p).x;
    r.fetches += 1;
    if (d < t) {
      occluding += 1.0;
      depthSum += d;
    }
  }
  float texels = float(size.x * size.y);
  r.occluders += texels * occluding / float(m);
  r.depthSum += texels * depthSum / float(m);
}

// Reads a node inside the region (with a pyramid level) and counts it: a node
// whose texels all occlude is added whole; returns true when it is ambiguous,
// with its min depth in `nodeMin`.
bool pnTraversalClassify(inout PnTraversal r, sampler2DArray pyramid, int level, ivec2 origin, float t,
                         out float nodeMin) {
  vec4 node = pnPyramidFetch(pyramid, level, origin);
  r.nodes += 1;
  r.fetches += 1;
  nodeMin = node.x;
  if (node.y < t) {
    float texels = float(1 << (2 * level));
    r.occluders += texels;
    r.depthSum += node.z * texels;
    return false;
  }
  return node.x < t;
}

// A node inside the region, with a pyramid level, that will not be descended:
// classified, and estimated by the leaf mode when ambiguous.
void pnTraversalVisitLeaf(inout PnTraversal r, sampler2DArray pyramid, sampler2D sampleTable, int level, ivec2 origin,
                          float t, int leafMode, ivec2 pixel) {
  float nodeMin;
  if (!pnTraversalClassify(r, pyramid, level, origin, t, nodeMin)) return;
  int side = 1 << level;
  if (leafMode == PN_LEAF_MIN) {
    float texels = float(side * side);
    r.occluders += texels;
    r.depthSum += nodeMin * texels;
  } else {
    pnTraversalSampleLeaf(r, pyramid, sampleTable, origin, ivec2(side), side, t, pixel);
  }
}

PnTraversal pnTraverseRegion(sampler2DArray pyramid, sampler2D sampleTable, ivec2 regionOrigin, ivec2 regionSize,
                             float receiverDepth, float bias, int leafSide, int leafMode, int nodeBudget,
                             ivec2 pixel) {
  PnTraversal r = PnTraversal(0.0, 0.0, 0.0, 0, 0);
  // The region is clipped to the map (and to the largest root), so every read is inside.
  int n = pnPyramidMapSize(pyramid);
  ivec2 regionStart = clamp(regionOrigin, ivec2(0), ivec2(n));
  ivec2 regionEnd = clamp(regionOrigin + max(regionSize, ivec2(0)), regionStart,
                          min(ivec2(n), regionStart + (1 << PN_TRAVERSAL_MAX_LEVEL)));
  ivec2 size = regionEnd - regionStart;
  r.texels = float(size.x * size.y);
  float t = receiverDepth - bias;
  if (isnan(t) || r.texels == 0.0) return r;

  int rootLevel = findMSB(max(size.x, size.y) - 1) + 1;
  int maxLevel = pnPyramidMaxLevel(pyramid);
  int budget = clamp(nodeBudget, 1, 1 << 26);
  int level = rootLevel;
  uint code = 0u;
  // One iteration per node, except that a node whose children are all leaves
  // handles them in the same iteration (they are never descended): the
  // iteration count stays a quarter of the node count, and no loop runs into
  // llvmpipe's cut-off of 65535 iterations per invocation, shared by all loops.
  int iterations = budget + 3 * rootLevel + 1;
  for (int it = 0; it < iterations; ++it) {
    int side = 1 << level;
    ivec2 origin = regionStart + side * ivec2(pnTraversalCompactBits(code), pnTraversalCompactBits(code >> 1));
    ivec2 lo = max(origin, regionStart);
    ivec2 hi = min(origin + side, regionEnd);
    bool descend = false;
    if (all(lessThan(lo, hi))) {
      bool inside = all(equal(lo, origin)) && all(equal(hi, origin + side));
      bool spent = r.nodes + 1 >= budget;
      if (inside && level <= maxLevel && (side <= leafSide || spent)) {
        pnTraversalVisitLeaf(r, pyramid, sampleTable, level, origin, t, leafMode, pixel);
      } else if (inside && level <= maxLevel) {
        float nodeMin;
        if (pnTraversalClassify(r, pyramid, level, origin, t, nodeMin)) {  // ambiguous: descend
          if ((side >> 1) <= leafSide) {
            int h = side >> 1;
            pnTraversalVisitLeaf(r, pyramid, sampleTable, level - 1, origin, t, leafMode, pixel);
            pnTraversalVisitLeaf(r, pyramid, sampleTable, level - 1, origin + ivec2(h, 0), t, leafMode, pixel);
            pnTraversalVisitLeaf(r, pyramid, sampleTable, level - 1, origin + ivec2(0, h), t, leafMode, pixel);
            pnTraversalVisitLeaf(r, pyramid, sampleTable, level - 1, origin + ivec2(h, h), t, leafMode, pixel);
          } else {
            descend = true;
          }
        }
      } else if (!spent) {
        r.nodes += 1;
        descend = true;  // straddles the region, or has no pyramid level
      } else {
        r.nodes += 1;
        pnTraversalSampleLeaf(r, pyramid, sampleTable, lo, hi - lo, side, t, pixel);
      }
    } else {
      r.nodes += 1;  // outside the region: visited, nothing to read
    }
    if (descend) {
      level -= 1;
      code *= 4u;
    } else {
      // Next node in Z order: the next sibling, climbing over every level whose last child this was.
      code += 1u;
      int climb = min(findLSB(code) >> 1, rootLevel - level);
      code >>= uint(2 * climb);
      level += climb;
      if (level == rootLevel) break;  // the root is done
    }
  }
  return r;
}

PnTraversal pnTraverseWindow(sampler2DArray pyramid, sampler2D sampleTable, PnWindow window, float receiverDepth,
                             float bias, int leafSide, int leafMode, int nodeBudget, ivec2 pixel) {
  return pnTraverseRegion(pyramid, sampleTable, window.origin, ivec2(window.side), receiverDepth, bias, leafSide,
                          leafMode, nodeBudget, pixel);
}

#endif  // PENUMBRA_TRAVERSAL_GLSL
