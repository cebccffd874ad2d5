// exact_pcss.glsl — exact PCSS in one call: the reference the other PCSS
// techniques approximate, brute force over every texel of its regions.
//
// description:
//   SPEC §4.8 ("exact PCSS"). For the receiver (u, v, d):
//     search  = PCSS's search width for d (blockers as near as the near plane,
//               light_model.glsl), the exact square of that side around (u, v)
//               (pcss_regions.glsl: pn_searchStart, pnEntryRect); no surface -> 1
//     blockers = every texel of the search square with depth < d - bias
//               (pcf.glsl: pnPcfWindow): mean = their depth sum / count; none -> 1
//     filter  = the square of side filterScale · penumbra (Eq. 1) around (u, v)
//               (pnFilterEntry)
//     visibility = 1 - (texels of the filter square with depth < d - bias) / its texels
//   The staged passes (pcss_search, pcss_scan in bands, pcss_filter, pcss_shade)
//   compute the same sums in the same row order: equal bit for bit.
//
// use:
//   float pnExactPcss(sampler2D depthMap, PnLight light, vec3 receiver, float bias, float filterScale)
//         receiver = (u, v, d) as pnLightProject gives (light_model.glsl); depthMap: the linear
//         light depth (R32F), texelFetch only
//   float pnExactPcss(sampler2D depthMap, PnLight light, vec3 receiver, vec2 receiverPlane, float bias,
//                     float filterScale)   with a receiver-plane depth bias (receiver_plane.glsl): each
//         texel compared with the plane at its centre (pcf.glsl's pnPcfWindowPlane); 0: the call above
//
// options:
//   PN_AREA_EDGES   0: the integer squares above. 1 (the default): both squares with area-weighted
//         edges (issue 51, docs/area-regions.md; the family's option, pcss_regions.glsl): region.glsl's
//         pnRegionArea of the entry's centre and side, read by pcf.glsl's pnPcfAreaPlane — every texel
//         weighed by its overlap; the blocker mean and the occluded fraction are area-weighted, and
//         move with the receiver by any fraction of a texel (no staircase on small maps)
//
// cost: one fetch per texel of both squares: O(s²) for a side-s region, the
//   cost the other techniques exist to avoid. (A driver that caps a loop's
//   iterations per invocation — llvmpipe: 65535 — cuts a region wider than
//   about 1000 texels short: the runner runs exact PCSS in bands of rows.)
//
// isa budget: vgprs 24, instructions 900, code 5120, scratch 0, loop 370, loops 880
//   (`penumbra isa --budgets`: the call as an engine compiles it, RDNA 2 wave64; docs/isa.md; the
//   area form, the default: PN_AREA_EDGES 0 takes 16 VGPRs and fewer instructions — docs/area-regions.md)

#ifndef PENUMBRA_EXACT_PCSS_GLSL
#define PENUMBRA_EXACT_PCSS_GLSL

#include "light_model.glsl"
#include "pcf.glsl"
#include "pcss_regions.glsl"

// `sums` + the rows [firstRow, firstRow + rowCount) of an entry's region — its integer square, or
// its square with area-weighted edges — in row order: the staged scan's bands (pcss_scan.comp) add
// up to the one call's scan, bit for bit.
PnPcf pn_exactPcssAddRows(sampler2D depthMap, vec4 entry, int n, vec3 receiver, vec2 receiverPlane, float bias,
                          int firstRow, int rowCount, PnPcf sums) {
#if PN_AREA_EDGES
  return pnPcfAddAreaRowsPlane(depthMap, pnEntryArea(entry, n, PN_REGION_EXACT), receiver, receiverPlane, bias,
                               firstRow, rowCount, sums);
#else
  PnRect rect = pnEntryRect(entry, n);
  return pnPcfAddRowsPlane(depthMap, rect.origin, rect.size, receiver, receiverPlane, bias, firstRow, rowCount, sums);
#endif
}

// The texels the region reads (before PN_PCF_MAX_SIDE): the staged scan's fetch count.
int pn_exactPcssRegionTexels(vec4 entry, int n) {
  ivec2 size = pnEntryRect(entry, n).size;
  return size.x * size.y;
}

PnPcf pn_exactPcssRegion(sampler2D depthMap, vec4 entry, int n, vec3 receiver, vec2 receiverPlane, float bias) {
  return pn_exactPcssAddRows(depthMap, entry, n, receiver, receiverPlane, bias, 0, textureSize(depthMap, 0).y,
                             pnPcfZero());
}

float pnExactPcss(sampler2D depthMap, PnLight light, vec3 receiver, vec2 receiverPlane, float bias,
                  float filterScale) {
  int n = int(light.mapSize);
  vec4 search = pn_searchStart(light, vec4(receiver, 1.0));
  if (pnEntryLit(search)) return 1.0;
  PnPcf blockers = pn_exactPcssRegion(depthMap, search, n, receiver, receiverPlane, bias);
  vec4 filterEntry = pnFilterEntry(light, search, pnPcfBlockerMean(blockers), blockers.occluders > 0.0, filterScale);
  if (pnEntryLit(filterEntry)) return 1.0;
  return 1.0 - pnPcfOccludedFraction(pn_exactPcssRegion(depthMap, filterEntry, n, receiver, receiverPlane, bias));
}

float pnExactPcss(sampler2D depthMap, PnLight light, vec3 receiver, float bias, float filterScale) {
  return pnExactPcss(depthMap, light, receiver, vec2(0.0), bias, filterScale);
}

#endif  // PENUMBRA_EXACT_PCSS_GLSL
