// traversal_pyramid.glsl — the traversal of traversal.glsl over the decreased
// multi-scale shadow map (depth_pyramid.glsl): HQEPCSS's structure.
//
// description:
//   traversal.glsl's rules (its header: classification, leaves, budget) over
//   depth_pyramid.glsl's (min, max, mean) levels. pnTraverseRegion takes any
//   rectangle, clipped to the map (the exact, non-power-of-two region, SPEC
//   §4.4 "beyond the paper"); its root is the smallest power-of-two square at
//   the region's origin that covers it. Nodes outside the region are skipped,
//   nodes straddling its border (or above the pyramid's last level) are
//   descended, never read. For the paper's power-of-two window (region.glsl)
//   the region is the window and the root itself. A sampled leaf reads the
//   pyramid's level 0.
//
// use:
//   PnTraversal pnTraverseRegion(sampler2DArray pyramid, sampler2D sampleTable,
//       ivec2 regionOrigin, ivec2 regionSize, float receiverDepth, float bias,
//       int leafSide, int leafMode, int nodeBudget, ivec2 pixel)
//   PnTraversal pnTraverseWindow(... PnWindow window ...)       the region.glsl window
//   PnTraversal pnTraverseAreaPlane(sampler2DArray pyramid, sampler2D sampleTable, PnArea area,
//       vec3 receiver, vec2 gradient, float bias, int leafSide, int leafMode, int nodeBudget, ivec2 pixel)
//       over an area (region.glsl's pnRegionArea: issue 51's continuous square) with a receiver
//       plane (receiver = (u, v, d), gradient: receiver_plane.glsl; 0: none): the walk covers its
//       texels (area.cover), a node inside them weighed by its overlap with the square
//       (pnRegionAreaOver: 1 a texel inside, a fraction on the edges), a wholly occluding or wholly
//       lit edge node weighed, not descended — but one of differing depths that occludes wholly,
//       whose mean is of whole texels, is ambiguous (descended, or at a leaf estimated); a sampled
//       leaf's samples sit inside its overlap. Leaf side 1 is exact: each texel with its overlap.
//       The rectangle forms above are this over pnRegionAreaOfRect, bit for bit what they were.
//   (PnTraversal, pnTraversalLeafSide, pnTraversalBlockerMean, pnTraversalOccludedFraction: traversal.glsl)
//
// cost: one fetch per node inside the region, 4^k <= 16 per sampled leaf;
//   nodes <= min(4/3 · side², nodeBudget + 3 · rootLevel + 1).

#ifndef PENUMBRA_TRAVERSAL_PYRAMID_GLSL
#define PENUMBRA_TRAVERSAL_PYRAMID_GLSL

#include "depth_pyramid.glsl"
#include "region.glsl"
#include "sample_table.glsl"
#include "traversal.glsl"

// One sample of a leaf part [lo, hi) over the pyramid's level 0, placed inside the part's overlap
// (offset, scale) with the area (as traversal_mip.glsl's pn_traversalSampleAt).
void pn_traversalSampleAt(inout float occluding, inout float depthSum, inout PnTraversal r, sampler2DArray pyramid,
                         vec2 position, ivec2 lo, ivec2 hi, vec2 offset, vec2 scale, PnTraversalTest test) {
  ivec2 p = pn_sampleTexelOver(position, lo, hi, offset, scale);
  pn_traversalCountSample(occluding, depthSum, r, pnPyramidFetch(pyramid, 0, p).x, p, test);
}

void pn_traversalSampleOne(inout float occluding, inout float depthSum, inout PnTraversal r, sampler2DArray pyramid,
                          sampler2D sampleTable, int first, int set, int i, int m, ivec2 lo, ivec2 hi, vec2 offset,
                          vec2 scale, PnTraversalTest test) {
  if (i >= m) return;
  pn_traversalSampleAt(occluding, depthSum, r, pyramid, pnSample(sampleTable, first + i, set), lo, hi, offset, scale,
                       test);
}

// The same over the pyramid's level 0, scaled to the overlap's area.
void pn_traversalSampleLeaf(inout PnTraversal r, sampler2DArray pyramid, sampler2D sampleTable, ivec2 lo,
                           ivec2 hi, vec2 offset, vec2 scale, int side, PnTraversalTest test, ivec2 pixel) {
  int k = pnSampleGroupLog4(side);
  int m = pnSampleCount(k);
  int first = pnSampleFirstColumn(k);
  int set = pnSampleSet(pixel);
  float occluding = 0.0;
  float depthSum = 0.0;
  // As over the mip chain: the first four without a loop (llvmpipe's loop cut-off).
  pn_traversalSampleOne(occluding, depthSum, r, pyramid, sampleTable, first, set, 0, m, lo, hi, offset, scale, test);
  if (m > 1) {
    pn_traversalSampleOne(occluding, depthSum, r, pyramid, sampleTable, first, set, 1, m, lo, hi, offset, scale, test);
    pn_traversalSampleOne(occluding, depthSum, r, pyramid, sampleTable, first, set, 2, m, lo, hi, offset, scale, test);
    pn_traversalSampleOne(occluding, depthSum, r, pyramid, sampleTable, first, set, 3, m, lo, hi, offset, scale, test);
  }
  for (int g = 4; g < PN_SAMPLE_MAX_COUNT; g += 4) {
    if (g >= m) break;
    pn_traversalSampleOne(occluding, depthSum, r, pyramid, sampleTable, first, set, g, m, lo, hi, offset, scale,
                          test);
    pn_traversalSampleOne(occluding, depthSum, r, pyramid, sampleTable, first, set, g + 1, m, lo, hi, offset, scale,
                          test);
    pn_traversalSampleOne(occluding, depthSum, r, pyramid, sampleTable, first, set, g + 2, m, lo, hi, offset, scale,
                          test);
    pn_traversalSampleOne(occluding, depthSum, r, pyramid, sampleTable, first, set, g + 3, m, lo, hi, offset, scale,
                          test);
  }
  pn_traversalAddSampled(r, scale.x * scale.y, occluding, depthSum, m);
}

// Reads a node inside the region (with a pyramid level) and counts it: a node
// whose texels all occlude (below the lowest of the test's thresholds over it)
// is added with its weight (its texels, or its overlap with an area); returns
// true when it is ambiguous, with its (min, max) depth in `nodeRange`. A wholly
// occluding node of differing depths that an area weighs by less than its
// texels is ambiguous too: its mean is of whole texels, so its depths are
// weighed where they are read (a descent, or a leaf's estimate).
bool pn_traversalClassify(inout PnTraversal r, sampler2DArray pyramid, int level, ivec2 origin, float weight,
                         PnTraversalTest test, out vec2 nodeRange) {
  vec4 node = pnPyramidFetch(pyramid, level, origin);
  r.nodes += 1;
  r.fetches += 1;
  nodeRange = node.xy;
  int side = 1 << level;
  vec2 t = pnReceiverPlaneThresholdRange(test.threshold, test.gradient, test.centre, origin, origin + side);
  if (node.y < t.x) {
    if (node.x != node.y && weight != float(side * side)) return true;
    r.occluders += weight;
    r.depthSum += node.z * weight;
    return false;
  }
  return node.x < t.y;
}

// A node inside the region, with a pyramid level, that will not be descended:
// classified, and estimated by the leaf mode when ambiguous (min and ramp
// against the test's threshold at the node's centre, over its weight; samples
// spread over its overlap with the area).
void pn_traversalVisitLeaf(inout PnTraversal r, sampler2DArray pyramid, sampler2D sampleTable, PnArea a, int level,
                          ivec2 origin, PnTraversalTest test, int leafMode, ivec2 pixel) {
  int side = 1 << level;
  vec2 range, offset, scale;
  pn_traversalPartOverlap(a, origin, origin + side, offset, scale);
  float weight = scale.x * scale.y;  // pnRegionAreaOver(a, origin, origin + side)
  if (!pn_traversalClassify(r, pyramid, level, origin, weight, test, range)) return;
  if (!pn_traversalSamples(leafMode)) {
    pn_traversalEstimateLeaf(r, leafMode, range.x, range.y, weight,
                            pn_traversalTestAtCentre(test, origin, origin + side));
  } else {
    pn_traversalSampleLeaf(r, pyramid, sampleTable, origin, origin + side, offset, scale,
                           pn_traversalSampleSide(leafMode, side), test, pixel);
  }
}

PnTraversal pnTraverseAreaPlane(sampler2DArray pyramid, sampler2D sampleTable, PnArea area, vec3 receiver,
                                vec2 gradient, float bias, int leafSide, int leafMode, int nodeBudget, ivec2 pixel) {
  ivec2 regionStart, regionEnd;
  PnTraversal r = pn_traversalBeginArea(area, pnPyramidMapSize(pyramid), regionStart, regionEnd);
  ivec2 size = regionEnd - regionStart;
  PnTraversalTest t = PnTraversalTest(receiver.z - bias, gradient, receiver.xy);
  if (isnan(t.threshold) || r.texels == 0.0) return r;

  int rootLevel = findMSB(max(size.x, size.y) - 1) + 1;
  int maxLevel = pnPyramidMaxLevel(pyramid);
  int budget = clamp(nodeBudget, 1, PN_TRAVERSAL_NO_BUDGET);
  int level = rootLevel;
  uint code = 0u;
  // One iteration per node, except that a node whose children are all leaves
  // handles them in the same iteration (they are never descended): the
  // iteration count stays a quarter of the node count, below llvmpipe's loop
  // cut-off (65535 iterations of a loop per invocation; traversal.md).
  int iterations = budget + 3 * rootLevel + 1;
  for (int it = 0; it < iterations; ++it) {
    int side = 1 << level;
    ivec2 origin = pn_traversalNodeOrigin(regionStart, side, code);
    ivec2 lo = max(origin, regionStart);
    ivec2 hi = min(origin + side, regionEnd);
    bool descend = false;
    if (all(lessThan(lo, hi))) {
      bool inside = all(equal(lo, origin)) && all(equal(hi, origin + side));
      bool spent = r.nodes + 1 >= budget;
      if (inside && level <= maxLevel && (side <= leafSide || spent)) {
        pn_traversalVisitLeaf(r, pyramid, sampleTable, area, level, origin, t, leafMode, pixel);
      } else if (inside && level <= maxLevel) {
        vec2 range;
        if (pn_traversalClassify(r, pyramid, level, origin, pnRegionAreaOver(area, origin, origin + side), t,
                                range)) {  // ambiguous: descend
          if ((side >> 1) <= leafSide) {
            int h = side >> 1;
            pn_traversalVisitLeaf(r, pyramid, sampleTable, area, level - 1, origin, t, leafMode, pixel);
            pn_traversalVisitLeaf(r, pyramid, sampleTable, area, level - 1, origin + ivec2(h, 0), t, leafMode, pixel);
            pn_traversalVisitLeaf(r, pyramid, sampleTable, area, level - 1, origin + ivec2(0, h), t, leafMode, pixel);
            pn_traversalVisitLeaf(r, pyramid, sampleTable, area, level - 1, origin + ivec2(h, h), t, leafMode, pixel);
          } else {
            descend = true;
          }
        }
      } else if (!spent) {
        r.nodes += 1;
        descend = true;  // straddles the region, or has no pyramid level
      } else {
        r.nodes += 1;
        vec2 offset, scale;
        pn_traversalPartOverlap(area, lo, hi, offset, scale);
        pn_traversalSampleLeaf(r, pyramid, sampleTable, lo, hi, offset, scale, pn_traversalSampleSide(leafMode, side), t,
                               pixel);
      }
    } else {
      r.nodes += 1;  // outside the region: visited, nothing to read
    }
    if (pn_traversalNext(level, code, descend, rootLevel)) break;  // the root is done
  }
  return r;
}

PnTraversal pn_traverseRegionPlane(sampler2DArray pyramid, sampler2D sampleTable, ivec2 regionOrigin,
                                  ivec2 regionSize, vec3 receiver, vec2 gradient, float bias, int leafSide,
                                  int leafMode, int nodeBudget, ivec2 pixel) {
  return pnTraverseAreaPlane(pyramid, sampleTable, pnRegionAreaOfRect(PnRect(regionOrigin, regionSize)), receiver,
                             gradient, bias, leafSide, leafMode, nodeBudget, pixel);
}

PnTraversal pnTraverseRegion(sampler2DArray pyramid, sampler2D sampleTable, ivec2 regionOrigin, ivec2 regionSize,
                             float receiverDepth, float bias, int leafSide, int leafMode, int nodeBudget,
                             ivec2 pixel) {
  return pn_traverseRegionPlane(pyramid, sampleTable, regionOrigin, regionSize, vec3(0.0, 0.0, receiverDepth),
                               vec2(0.0), bias, leafSide, leafMode, nodeBudget, pixel);
}

PnTraversal pnTraverseWindow(sampler2DArray pyramid, sampler2D sampleTable, PnWindow window, float receiverDepth,
                             float bias, int leafSide, int leafMode, int nodeBudget, ivec2 pixel) {
  return pnTraverseRegion(pyramid, sampleTable, window.origin, ivec2(window.side), receiverDepth, bias, leafSide,
                          leafMode, nodeBudget, pixel);
}

#endif  // PENUMBRA_TRAVERSAL_PYRAMID_GLSL
