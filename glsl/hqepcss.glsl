// hqepcss.glsl — HQEPCSS (high-quality, efficient PCSS) in one call: the
// refined blocker search over the decreased pyramid with min-estimated
// leaves, then exact PCF over the filter region.
//
// description:
//   SPEC §4.8 ("HQEPCSS"), the baseline Fast PCSS's paper compares with:
//     search  = the search region refined `refineIterations` times from the
//               pyramid's exact square min (pcss_regions.glsl: pnSearchEntry); lit -> 1
//     blockers = traversal of the search region (regionMode: the paper's window,
//               or the exact square) over the pyramid (traversal.glsl,
//               pnTraverseRegion) whose ambiguous leaves count every texel as
//               a blocker at the leaf's min (PN_LEAF_MIN): mean = sum / count
//     filter  = pnFilterEntry: side filterScale · penumbra; no blocker -> 1
//     visibility = 1 - exact PCF over the filter square (pcf.glsl)
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
// cost: Step 3 4 fetches a refinement; the blocker traversal one fetch a node;
//   the PCF one fetch per texel of the filter square (O(s²)).
//
// isa budget: vgprs 40, instructions 1800, code 9216, scratch 0, loop 1450, loops 2200
//   (`penumbra isa --budgets`: the call as an engine compiles it, RDNA 2 wave64; docs/isa.md)

#ifndef PENUMBRA_HQEPCSS_GLSL
#define PENUMBRA_HQEPCSS_GLSL

#include "depth_pyramid.glsl"
#include "hqepcss.h"
#include "light_model.glsl"
#include "pcf.glsl"
#include "pcss_regions_pyramid.glsl"
#include "traversal_pyramid.glsl"

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

float pnHqepcss(sampler2DArray pyramid, sampler2D depthMap, PnLight light, vec3 receiver, vec2 receiverPlane,
                PnHqepcssSettings s) {
  int n = int(light.mapSize);
  vec4 search = pnSearchEntryPlane(pyramid, light, vec4(receiver, 1.0), receiverPlane, s.bias, s.refineIterations);
  if (pnEntryLit(search)) return 1.0;
  PnRect region = pnEntryRegion(search, n, s.regionMode);
  // Min leaves take no samples: the sample table is never read (the map stands in for it).
  PnTraversal blockers = pn_traverseRegionPlane(pyramid, depthMap, region.origin, region.size, receiver,
                                                receiverPlane, s.bias,
                                                pnTraversalLeafSide(s.leafSide, s.leafDivisor, region.size),
                                                PN_LEAF_MIN, s.nodeBudget, ivec2(0));
  bool hasBlocker = blockers.occluders > 0.0;
  vec4 filterEntry = pnFilterEntry(light, search, pnTraversalBlockerMean(blockers),
                                   hasBlocker, s.filterScale);
  if (pnEntryLit(filterEntry)) return 1.0;
  PnRect filterRect = pnEntryRect(filterEntry, n);
  return 1.0 - pnPcfOccludedFraction(pnPcfWindowPlane(depthMap, filterRect.origin, filterRect.size, receiver,
                                                       receiverPlane, s.bias));
}

float pnHqepcss(sampler2DArray pyramid, sampler2D depthMap, PnLight light, vec3 receiver, PnHqepcssSettings s) {
  return pnHqepcss(pyramid, depthMap, light, receiver, vec2(0.0), s);
}

#endif  // PENUMBRA_HQEPCSS_GLSL
