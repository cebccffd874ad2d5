// pcss_regions_pyramid.glsl — pcss_regions.glsl's search entry (Step 3) with
// the region's min read from the decreased multi-scale shadow map
// (depth_pyramid.glsl): HQEPCSS's structure.
//
// description:
//   pcss_regions.glsl's Step 3 (its header: the start, the lit decision, the
//   lossless refinement), its zmin the min of the pyramid's square covering
//   the exact region (pnPyramidSquareMinMax: 4 fetches), where the mip
//   chain's call reads the aligned nodes that touch it.
//
// use:
//   vec4  pnSearchEntry(sampler2DArray pyramid, PnLight light, vec4 receiver, float bias,
//                       int iterations)                          receiver = G-buffer (u, v, d, valid)
//   vec4  pnSearchEntryPlane(sampler2DArray pyramid, PnLight light, vec4 receiver, vec2 gradient, float bias,
//                            int iterations)   with a receiver plane (receiver_plane.glsl): lit when the
//                          region's min is not below the plane's highest threshold over the region;
//                          gradient 0 is pnSearchEntry exactly
//
// cost: 4 fetches per refinement iteration.

#ifndef PENUMBRA_PCSS_REGIONS_PYRAMID_GLSL
#define PENUMBRA_PCSS_REGIONS_PYRAMID_GLSL

#include "depth_pyramid.glsl"
#include "pcss_regions.glsl"

// Min depth over a square that covers the entry's exact region (4 fetches).
float pn_searchRegionMin(sampler2DArray pyramid, vec4 entry) {
  int n = pnPyramidMapSize(pyramid);
  PnRect r = pnEntryRect(entry, n);
  if (r.size.x == 0 || r.size.y == 0) return pn_pyramidFar();
  return pnPyramidSquareMinMax(pyramid, r.origin, max(r.size.x, r.size.y)).x;
}

vec4 pnSearchEntryPlane(sampler2DArray pyramid, PnLight light, vec4 receiver, vec2 gradient, float bias,
                        int iterations) {
  int n = pnPyramidMapSize(pyramid);
  vec4 entry = pn_searchStart(light, receiver);
  for (int i = 0; i < PN_REFINE_MAX_ITERATIONS; ++i) {
    if (i >= iterations || pnEntryLit(entry)) break;
    bool done;
    entry = pn_searchRefinePlane(light, n, entry, pn_searchRegionMin(pyramid, entry), receiver.xy, gradient, bias, done);
    if (done) break;
  }
  return entry;
}

vec4 pnSearchEntry(sampler2DArray pyramid, PnLight light, vec4 receiver, float bias, int iterations) {
  return pnSearchEntryPlane(pyramid, light, receiver, vec2(0.0), bias, iterations);
}

#endif  // PENUMBRA_PCSS_REGIONS_PYRAMID_GLSL
