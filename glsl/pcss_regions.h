// pcss_regions.h — the constants that glsl/pcss_regions.glsl and the C++
// runner share: the region modes (runner/pipeline/pcss_settings.h RegionMode,
// static_asserted equal in runner/check/region_check.cpp), the side that marks
// a lit entry and the refinement's loop bound (the settings' limit on refine
// iterations). Valid as GLSL and as C++: only comments and guarded #defines.
// An engine may define PN_REFINE_MAX_ITERATIONS before including
// pcss_regions.glsl.

#ifndef PENUMBRA_PCSS_REGIONS_H
#define PENUMBRA_PCSS_REGIONS_H

// Loop bound of the search region's refinement (HQEPCSS).
#ifndef PN_REFINE_MAX_ITERATIONS
#define PN_REFINE_MAX_ITERATIONS 16
#endif

// The side s of an entry known to be lit: no region, nothing to do.
#define PN_REGION_LIT -1.0

// Which texels stand for a region of centre (x, y) and side s: the paper's
// power-of-two window (Steps 1-7), the n×n texels nearest the centre
// (pnRegionSquare), or the window's side centred on (x, y).
#define PN_REGION_WINDOW 0
#define PN_REGION_EXACT 1
#define PN_REGION_CENTRED 2

#endif  // PENUMBRA_PCSS_REGIONS_H
