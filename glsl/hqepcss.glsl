// hqepcss.glsl — HQEPCSS (high-quality, efficient PCSS) in one call: the
// refined blocker search over the decreased pyramid with min-estimated
// leaves, then exact PCF over the filter region.
//
// description:
//   SPEC §4.8 ("HQEPCSS"), the baseline Fast PCSS's paper compares with:
//     search  = the search region refined `refineIterations` times from the
//               pyramid's exact square min (pcss_regions.glsl: pnSearchEntry); lit -> 1
//     blockers = traversal of the search region (regionMode: the paper's window,
//               or the exact square) over the pyramid (traversal_pyramid.glsl's
//               pnTraverseRegion, walked lean: pn_hqepcssBlockers) whose ambiguous
//               leaves count every texel as a blocker at the leaf's min
//               (PN_LEAF_MIN): mean = sum / count
//     filter  = pnFilterEntry: side filterScale · penumbra; no blocker -> 1
//     visibility = 1 - exact PCF over the filter square (pcf.glsl, as exact_pcss.glsl reads it)
//   The staged passes compute the same numbers: equal bit for bit.
//
// use:
//   float pnHqepcss(sampler2DArray pyramid, sampler2D depthMap, PnLight light, vec3 receiver,
//                   PnHqepcssSettings settings)
//   float pnHqepcss(sampler2DArray pyramid, sampler2D depthMap, PnLight light, vec3 receiver,
//                   vec2 receiverPlane, PnHqepcssSettings settings)
//         with a receiver-plane depth bias (receiver_plane.glsl: the receiver's light depth per
//         texel, e.g. pnReceiverPlaneGradient of its derivatives): every test — the search's lit
//         decision, each node, each PCF texel — against the plane at that texel; vec2(0) is the
//         call above exactly
//   PnHqepcssSettings pnHqepcssDefaults(float bias)    refine 8, window regions, leaf 8
//         receiver = (u, v, d) as pnLightProject gives; pyramid: depth_pyramid.glsl's decreased
//         pyramid of the map; depthMap: the map (linear light depth), for the PCF
//
// options:
//   PN_HQEPCSS_ABLATIONS   defined before the include: settings.nodeBudget below
//                          PN_TRAVERSAL_NO_BUDGET runs traversal_pyramid.glsl's general walk with its
//                          budget. Without it the budget is not read (the call's walk has none:
//                          pn_hqepcssBlockers) and an engine's program holds one walk, not two.
//   PN_AREA_EDGES          (pcss_regions.glsl, issue 51, docs/area-regions.md) 1 (the default): the filter square
//                          with area-weighted edges (exact_pcss.glsl's PCF over pnEntryArea: every
//                          texel weighed by its overlap), and with regionMode PN_REGION_EXACT the
//                          search square too (traversal_pyramid.glsl's area rules: a node weighed by
//                          its overlap; one of differing depths that occludes wholly is ambiguous)
//
// cost: Step 3 4 fetches a refinement; the blocker traversal one fetch a node;
//   the PCF one fetch per texel of the filter square (O(s²)).
//
// isa budget: vgprs 32, instructions 1020, code 5120, scratch 0, loop 350, loops 990
//   (`penumbra isa --budgets`: the call as an engine compiles it, RDNA 2 wave64; docs/isa.md; the
//   area form, the default: PN_AREA_EDGES 0 takes 917 instructions — docs/area-regions.md)

#ifndef PENUMBRA_HQEPCSS_GLSL
#define PENUMBRA_HQEPCSS_GLSL

#include "depth_pyramid.glsl"
#include "exact_pcss.glsl"  // the filter's PCF, as exact PCSS reads its squares
#include "hqepcss.h"
#include "light_model.glsl"
#include "pcf.glsl"
#include "pcss_regions_pyramid.glsl"
#include "traversal.glsl"
#ifdef PN_HQEPCSS_ABLATIONS
#include "traversal_pyramid.glsl"  // the general walk, for a budget
#endif

struct PnHqepcssSettings {
  float bias;            // light-depth units: a texel occludes when its depth < d - bias
  float filterScale;     // c: filter side = c · penumbra
  int refineIterations;  // 0..PN_REFINE_MAX_ITERATIONS
  int regionMode;        // the blocker search's region: PN_REGION_WINDOW (the paper's), _EXACT or _CENTRED
  int leafSide;          // nodes of this side or smaller are estimated at their min
  int leafDivisor;       // > 0: the leaf side grows to the region's side / leafDivisor
  int nodeBudget;        // per traversal, >= 1
};

PnHqepcssSettings pnHqepcssDefaults(float bias) {
  return PnHqepcssSettings(bias, 1.0, PN_HQEPCSS_REFINE_ITERATIONS, PN_REGION_WINDOW, PN_HQEPCSS_LEAF_SIDE, 0,
                           PN_TRAVERSAL_NO_BUDGET);
}

// The blocker traversal without a node budget (every setting but nodeBudget): traversal_pyramid.glsl's
// walk in the same Z order with the same sums — so the same result, bit for bit — written for the
// wave as Fast PCSS's shipped walk is (docs/isa.md, "The lean call"): a cursor of the node relative to
// the root, (x, y) at `level`, whose next node climbs the trailing ones of x & y; one pyramid fetch a
// node; leaves (side <= leafSide) estimated at their min in the step that reads them, one node a step
// (the general walk reads a node's four leaves in its step). Nodes straddling the region (only a
// window or a rectangle the pyramid's map clips: a light.mapSize that is not the pyramid's) or above
// the pyramid's last level descend unread, as there. With PN_AREA_EDGES a node is weighed by its
// overlap with the area, as there.
PnTraversal pn_hqepcssBlockers(sampler2DArray pyramid, PnArea area, vec3 receiver, vec2 gradient, float bias,
                               int leafSide) {
  ivec2 start, end;
  PnTraversal r = pn_traversalBeginArea(area, pnPyramidMapSize(pyramid), start, end);
  PnTraversalTest test = PnTraversalTest(receiver.z - bias, gradient, receiver.xy);
  ivec2 size = end - start;
  int top = findMSB(max(size.x, size.y) - 1) + 1;  // the root: the least power of two over the region
  int maxLevel = pnPyramidMaxLevel(pyramid);
  int level = top;
  ivec2 node = ivec2(0);
  bool empty = isnan(test.threshold) || any(equal(start, end));  // no texel (r.texels is not read)
  for (int it = 0; it < PN_TRAVERSAL_CURSOR_STEPS && !empty; ++it) {
    int side = 1 << level;
    ivec2 origin = start + (node << level);
    ivec2 lo = max(origin, start), hi = min(origin + side, end);
    bool descend = false;
    if (all(lessThan(lo, hi))) {
      if (all(equal(lo, origin)) && all(equal(hi, origin + side)) && level <= maxLevel) {
        vec4 v = texelFetch(pyramid, ivec3(origin, level), 0);
        vec2 t = pnReceiverPlaneThresholdRange(test.threshold, test.gradient, test.centre, origin, origin + side);
        float texels = float(side * side);
        bool whole = v.y < t.x;
#if PN_AREA_EDGES
        // Its overlap with the square; an edge node of differing depths is ambiguous (its mean is of whole texels).
        float weight = pnRegionAreaOver(area, origin, origin + side);
        whole = whole && (v.x == v.y || weight == texels);
        texels = weight;
#endif
        if (whole) {  // every texel occludes: its mean times its weight
          r.occluders += texels;
          r.depthSum += v.z * texels;
        } else if (v.x < t.y) {  // ambiguous: a leaf at its min (PN_LEAF_MIN), or its children
          descend = side > leafSide;
          if (!descend) {
            r.occluders += texels;
            r.depthSum += v.x * texels;
          }
        }
      } else {
        descend = true;
      }
    }
    if (pn_traversalCursorNext(node, level, descend, top - 1)) break;  // the root (or its last child) done
  }
  return r;
}

float pnHqepcss(sampler2DArray pyramid, sampler2D depthMap, PnLight light, vec3 receiver, vec2 receiverPlane,
                PnHqepcssSettings s) {
  int n = int(light.mapSize);
  vec4 search = pnSearchEntryPlane(pyramid, light, vec4(receiver, 1.0), receiverPlane, s.bias, s.refineIterations);
  if (pnEntryLit(search)) return 1.0;
  PnArea region = pnEntryArea(search, n, s.regionMode);
  int leafSide = pnTraversalLeafSide(s.leafSide, s.leafDivisor, region.cover.size);
  PnTraversal blockers;
#ifdef PN_HQEPCSS_ABLATIONS
  if (s.nodeBudget < PN_TRAVERSAL_NO_BUDGET)  // the budget's ablation: the general walk
    // Min leaves take no samples: the sample table is never read (the map stands in for it).
    blockers = pnTraverseAreaPlane(pyramid, depthMap, region, receiver, receiverPlane, s.bias, leafSide, PN_LEAF_MIN,
                                   s.nodeBudget, ivec2(0));
  else
#endif
    blockers = pn_hqepcssBlockers(pyramid, region, receiver, receiverPlane, s.bias, leafSide);
  bool hasBlocker = blockers.occluders > 0.0;
  vec4 filterEntry = pnFilterEntry(light, search, pnTraversalBlockerMean(blockers),
                                   hasBlocker, s.filterScale);
  if (pnEntryLit(filterEntry)) return 1.0;
  return 1.0 - pnPcfOccludedFraction(pn_exactPcssRegion(depthMap, filterEntry, n, receiver, receiverPlane, s.bias));
}

float pnHqepcss(sampler2DArray pyramid, sampler2D depthMap, PnLight light, vec3 receiver, PnHqepcssSettings s) {
  return pnHqepcss(pyramid, depthMap, light, receiver, vec2(0.0), s);
}

#endif  // PENUMBRA_HQEPCSS_GLSL
