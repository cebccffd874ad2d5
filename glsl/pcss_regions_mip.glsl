// pcss_regions_mip.glsl — pcss_regions.glsl's search entry (Step 3) with the
// region's min read from the aligned min/max mip chain (minmax_mip.glsl):
// Fast PCSS's structure.
//
// description:
//   pcss_regions.glsl's Step 3 (its header: the start, the lit decision, the
//   lossless refinement), its zmin the min over the chain's aligned nodes that
//   touch the square covering the exact region (pnMipSquareMinMax, <= 9
//   fetches): never above the square's min, so the lit decision stays
//   conservative and refinement lossless.
//
// use:
//   vec4  pnSearchEntryMip(sampler2D mip, int mapSize, PnLight light, vec4 receiver, float bias,
//                          int iterations)   receiver = G-buffer (u, v, d, valid); zmin from the
//                          aligned mip chain (minmax_mip.glsl): over the aligned nodes touching the
//                          square (<= 9 fetches), a superset (pcss_regions_pyramid.glsl: the same
//                          from the pyramid)
//   vec4  pnSearchEntryMipCounted(... the same ..., out int refinements)   and how many refinements read
//                          the chain (<= 9 fetches each: the call's cost)
//   vec4  pnSearchEntryMipPlane(sampler2D mip, int mapSize, PnLight light, vec4 receiver, vec2 gradient,
//                               float bias, int iterations, out int refinements)
//                          with a receiver plane (receiver_plane.glsl): lit when zmin is not below the
//                          plane's highest threshold over the region; gradient 0 is ...MipCounted exactly
//
// cost: <= 9 fetches per refinement iteration.

#ifndef PENUMBRA_PCSS_REGIONS_MIP_GLSL
#define PENUMBRA_PCSS_REGIONS_MIP_GLSL

#include "minmax_mip.glsl"
#include "pcss_regions.glsl"

// The same from the aligned mip chain: the min over the aligned nodes that
// touch that square (<= 9 fetches) — never above the square's min, so the lit
// decision stays conservative and refinement lossless.
// The entry's rectangle `r` lies in the map, clipped to the chain too (n <= P), so the square of
// side max(w, h) at its origin needs clipping on the far side only, and every node read is in the
// chain (pnMipSquareMinMax's cover of that square); the chain's shape is read once, by the caller.
float pn_searchRegionMinMip(sampler2D mip, PnMipShape shape, int n, PnRect r) {
  if (r.size.x == 0 || r.size.y == 0) return pn_mipFar();
  return pn_mipRectMinMax(mip, shape, r.origin, min(r.origin + max(r.size.x, r.size.y), ivec2(n))).x;
}

vec4 pnSearchEntryMipPlane(sampler2D mip, int mapSize, PnLight light, vec4 receiver, vec2 gradient, float bias,
                           int iterations, out int refinements) {
  vec4 entry = pn_searchStart(light, receiver);
  refinements = 0;
  PnMipShape shape = pn_mipShape(mip);
  int n = max(min(mapSize, shape.rows), 1);
  vec2 centre = pn_regionSquareCentre(receiver.xy, n);  // every refinement's (the entry's u, v)
  for (int i = 0; i < PN_REFINE_MAX_ITERATIONS; ++i) {
    if (i >= iterations || pnEntryLit(entry)) break;
    bool done;
    refinements += 1;
    // The entry's rectangle (pnEntryRect, its centre made once above), for the min and the plane's range.
#if PN_AREA_EDGES
    PnRect r = pn_regionAreaAbout(centre, entry.w, n).cover;
#else
    PnRect r = pn_regionSquareAbout(centre, entry.w, n);
#endif
    entry = pn_searchRefineRect(light, entry, r, pn_searchRegionMinMip(mip, shape, n, r), receiver.xy, gradient, bias,
                                done);
    if (done) break;
  }
  return entry;
}

vec4 pnSearchEntryMipCounted(sampler2D mip, int mapSize, PnLight light, vec4 receiver, float bias, int iterations,
                             out int refinements) {
  return pnSearchEntryMipPlane(mip, mapSize, light, receiver, vec2(0.0), bias, iterations, refinements);
}

vec4 pnSearchEntryMip(sampler2D mip, int mapSize, PnLight light, vec4 receiver, float bias, int iterations) {
  int refinements;
  return pnSearchEntryMipCounted(mip, mapSize, light, receiver, bias, iterations, refinements);
}

#endif  // PENUMBRA_PCSS_REGIONS_MIP_GLSL
