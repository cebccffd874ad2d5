// pcss_regions_query.h — what passes/pcss_regions_query.comp and its runner
// side (runner/pass_runners/pcss_regions_pass.cpp) share: binding points, the query
// kinds and the parameter block. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_PCSS_REGIONS_QUERY_H
#define PENUMBRA_PASSES_PCSS_REGIONS_QUERY_H

#include "light_fields.h"
#include "uniform_block.h"

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well;
// images first, within GLSL ES 3.10's minimum of 4 image units.
#define PN_PCSS_REGIONS_QUERY_ENTRY_BINDING 0    // image2D, rgba32f out: the entry (d, x, y, s)
#define PN_PCSS_REGIONS_QUERY_RECT_BINDING 1     // image2D, rgba32f out: pnEntryRect (origin, size)
#define PN_PCSS_REGIONS_QUERY_WINDOW_BINDING 2   // image2D, rgba32f out: pnEntryWindow (origin, side), pnEntryLit
                                                 // + 2 × the refinements of SEARCH_MIP_COUNTED (else 0)
#define PN_PCSS_REGIONS_QUERY_KEY_BINDING 3      // image2D, rgba32f out: pnEntryLinkKey
#define PN_PCSS_REGIONS_QUERY_PYRAMID_BINDING 4  // sampler2DArray: the depth pyramid (depth_pyramid.glsl)
#define PN_PCSS_REGIONS_QUERY_A_BINDING 5        // sampler2D, RGBA32F: receiver (u, v, d, valid) or entry
#define PN_PCSS_REGIONS_QUERY_B_BINDING 6        // sampler2D, RGBA32F: (kind, region mode, iterations, has blocker)
#define PN_PCSS_REGIONS_QUERY_C_BINDING 7        // sampler2D, RGBA32F: (bias, blocker mean, filter scale, -); plane: (bias, gradient, -)
#define PN_PCSS_REGIONS_QUERY_PARAMS_BINDING 8
#define PN_PCSS_REGIONS_QUERY_MIP_BINDING 9      // sampler2D: the aligned min/max mip chain (minmax_mip.glsl)

// Query kinds (B.x): what produces the entry whose regions the pass then reports.
#define PN_PCSS_REGIONS_QUERY_SEARCH 0  // pnSearchEntry(pyramid, light, A, C.x, int(B.z)); B.y: the mode of the regions it reports
#define PN_PCSS_REGIONS_QUERY_FILTER 1  // pnFilterEntry(light, A, C.y, B.w != 0, C.z)
#define PN_PCSS_REGIONS_QUERY_ENTRY 2   // A itself
#define PN_PCSS_REGIONS_QUERY_SEARCH_MIP 3  // pnSearchEntryMip(mip, N, light, A, C.x, int(B.z))
#define PN_PCSS_REGIONS_QUERY_SEARCH_MIP_COUNTED 4  // pnSearchEntryMipCounted: the same, and its refinements
#define PN_PCSS_REGIONS_QUERY_SEARCH_MIP_PLANE 5  // pnSearchEntryMipPlane: the same with the receiver plane's gradient C.yz
#define PN_PCSS_REGIONS_QUERY_SEARCH_PLANE 6  // pnSearchEntryPlane over the pyramid: the same as search, gradient C.yz

PN_UNIFORM_BLOCK(PnPcssRegionsQueryParams, PN_PCSS_REGIONS_QUERY_PARAMS_BINDING)
  PN_LIGHT_FIELDS  // PnLight (light_model.glsl); mapSize is N, the pyramid's size
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_PCSS_REGIONS_QUERY_H
