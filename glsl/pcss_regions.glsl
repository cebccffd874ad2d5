// pcss_regions.glsl — the search and filter regions of PCSS (Steps 3 and 4
// of Fast PCSS), as (d, x, y, s) entries of the search- and filter-region maps.
//
// description:
//   Seed 000 §1, SPEC §4.7. An entry is (receiver light depth d, region
//   centre x, y in shadow-map texels, region side s in texels); s < 0
//   (PN_REGION_LIT, pcss_regions.h) marks a pixel known to be lit: no region, nothing to do.
//   Step 3 — search region: PCSS's blocker-search width for d (blockers as
//   near as the near plane, light_model.glsl), then, when refining (HQEPCSS),
//   repeated at most `iterations` times:
//     zmin = min depth of a square covering the region (pcss_regions_mip.glsl:
//            the mip chain's aligned nodes, <= 9 fetches; pcss_regions_pyramid.glsl:
//            the pyramid's square, 4);
//     zmin >= d - bias            -> nothing in the region occludes: lit;
//     s' = width a blocker at zmin needs (light_model.glsl);
//     s' >= s                     -> stop; else s = s' and repeat.
//   The width is decreasing in the blocker depth, so every blocker that can
//   shadow the receiver (depth >= the true zmin) lies in the shrunk region
//   as long as zmin is the min of a square covering the region: Step 3 reads
//   the square that covers pnRegionSquare's rectangle in every region mode,
//   so no pixel with a blocker in its search region is marked lit and
//   refinement is lossless (SPEC §4.7). The region mode applies from Step 4
//   on: the paper's power-of-two window, pinned to the region's clamped
//   corner and rounded down, can miss blockers on its +u/+v side, and read
//   for the lit decision it marked shadowed pixels lit (issue 11).
//   Step 4 — filter region: from the blocker mean dz (Step 4's traversal),
//   penumbra by Eq. (1) in texels at the receiver (light_model.glsl), side
//   s = c · penumbra; no blocker -> lit.
//   A pixel without a surface, a NaN depth, or a region that misses the map
//   is lit. A zero-size light gives s = 0: one texel, a hard shadow.
//
// use:
//   vec4  pnFilterEntry(PnLight light, vec4 searchEntry, float blockerMean, bool hasBlocker, float scale)
//   PnRect pnEntryRect(vec4 entry, int mapSize)                  the exact region of an entry (with
//                                                  PN_AREA_EDGES, the texels its square touches: its cover)
//   PnArea pnEntryArea(vec4 entry, int mapSize, int regionMode)  the region Steps 4 and 5 weigh: with
//         PN_AREA_EDGES in the exact mode the continuous square (pnRegionArea), else pnEntryRegion's
//         rectangle, every texel of weight 1 (pnRegionAreaOfRect)
//   PnWindow pnEntryWindow(vec4 entry, int mapSize, int regionMode)  its power-of-two window (region.glsl)
//   PnRect pnEntryRegion(vec4 entry, int mapSize, int regionMode)   the texels Steps 4 and 5 read:
//                                                  the exact region, or the window as a rectangle
//   bool  pnEntryLit(vec4 entry)
//   vec4  pnEntryLinkKey(vec4 entry, int mapSize, int regionMode)   what the reuse scheme compares
//         (reuse.glsl): in the window modes the side is the window's power of two, as the paper's
//         maps hold it (§5.2: "the sizes are already approximated", hence sigma1 = 0); else the entry
//   regionMode: PN_REGION_WINDOW (the paper's Steps 1-7), PN_REGION_EXACT (pnRegionSquare),
//               PN_REGION_CENTRED (the window's side, centred on the region: pnRegionApproximateCentred);
//               pcss_regions.h, shared with the runner
//
// options:
//   PN_AREA_EDGES 1             (the default) the exact region is the continuous square of side s
//                               with area-weighted edges (issue 51, docs/area-regions.md) for every
//                               technique of the family that reads it (exact PCSS, Fast PCSS,
//                               HQEPCSS): each texel counts with its overlap, so a region moves with
//                               its receiver by any fraction of a texel; Step 3 reads the min over its
//                               cover. 0: the integer squares of whole texels (pnRegionSquare), a
//                               step at every texel on a small map, but fewer registers and
//                               instructions (the modules' pages give both forms' isa)
//   PN_REFINE_MAX_ITERATIONS 16   loop bound of the refinement (pcss_regions.h, shared with the runner)
//
// cost: entries: ALU only (the search's fetches: pcss_regions_mip.glsl, pcss_regions_pyramid.glsl).

#ifndef PENUMBRA_PCSS_REGIONS_GLSL
#define PENUMBRA_PCSS_REGIONS_GLSL

#include "light_model.glsl"
#include "pcss_regions.h"
#include "receiver_plane.glsl"
#include "region.glsl"

#ifndef PN_AREA_EDGES
#define PN_AREA_EDGES 1
#endif

bool pnEntryLit(vec4 entry) {
  return !(entry.w >= 0.0);
}

PnRect pnEntryRect(vec4 entry, int mapSize) {
#if PN_AREA_EDGES
  return pnRegionArea(entry.yz, entry.w, mapSize).cover;
#else
  return pnRegionSquare(entry.yz, entry.w, mapSize);
#endif
}

PnWindow pnEntryWindow(vec4 entry, int mapSize, int regionMode) {
  if (regionMode == PN_REGION_CENTRED) return pnRegionApproximateCentred(entry.yz, entry.w, mapSize);
  return pnRegionApproximate(entry.yz, entry.w, mapSize);
}

vec4 pnEntryLinkKey(vec4 entry, int mapSize, int regionMode) {
  if (regionMode == PN_REGION_EXACT || pnEntryLit(entry)) return entry;
  return vec4(entry.xyz, float(pnEntryWindow(entry, mapSize, regionMode).side));
}

// Step 3's start: PCSS's search width, or lit for a pixel without a surface.
vec4 pn_searchStart(PnLight light, vec4 receiver) {
  float d = receiver.z;
  if (receiver.w == 0.0 || isnan(d)) return vec4(0.0, 0.0, 0.0, PN_REGION_LIT);
  return vec4(d, receiver.xy, pnLightSearchWidthTexels(light, d));
}

// One refinement step from the region's min depth zmin: lit when no depth is
// below the receiver plane's highest threshold over the entry's region (the
// receiver's depth minus the bias when gradient is 0), else shrunk, or `done`.
// `r`: the entry's rectangle (pnEntryRect), which a caller that has it hands on.
vec4 pn_searchRefineRect(PnLight light, vec4 entry, PnRect r, float zmin, vec2 centre, vec2 gradient, float bias,
                         out bool done) {
  done = true;
  float highestThreshold = pnReceiverPlaneThresholdRange(entry.x - bias, gradient, centre, r.origin, r.origin + r.size).y;
  if (!(zmin < highestThreshold)) return vec4(entry.xyz, PN_REGION_LIT);
  float side = pnLightBlockerWindowTexels(light, entry.x, zmin);
  if (!(side < entry.w)) return entry;
  done = false;
  return vec4(entry.xyz, side);
}

vec4 pn_searchRefinePlane(PnLight light, int mapSize, vec4 entry, float zmin, vec2 centre, vec2 gradient, float bias,
                          out bool done) {
  return pn_searchRefineRect(light, entry, pnEntryRect(entry, mapSize), zmin, centre, gradient, bias, done);
}

PnRect pnEntryRegion(vec4 entry, int mapSize, int regionMode) {
  if (regionMode == PN_REGION_EXACT) return pnEntryRect(entry, mapSize);
  PnWindow w = pnEntryWindow(entry, mapSize, regionMode);
  return PnRect(w.origin, ivec2(w.side));
}

PnArea pnEntryArea(vec4 entry, int mapSize, int regionMode) {
#if PN_AREA_EDGES
  if (regionMode == PN_REGION_EXACT) return pnRegionArea(entry.yz, entry.w, mapSize);
#endif
  return pnRegionAreaOfRect(pnEntryRegion(entry, mapSize, regionMode));
}

vec4 pnFilterEntry(PnLight light, vec4 searchEntry, float blockerMean, bool hasBlocker, float scale) {
  if (pnEntryLit(searchEntry) || !hasBlocker) return vec4(searchEntry.xyz, PN_REGION_LIT);
  float side = scale * pnLightPenumbraTexels(light, searchEntry.x, blockerMean);
  return vec4(searchEntry.xyz, (side >= 0.0 && !isinf(side)) ? side : 0.0);
}

#endif  // PENUMBRA_PCSS_REGIONS_GLSL
