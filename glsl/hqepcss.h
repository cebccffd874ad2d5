// hqepcss.h — HQEPCSS's defaults (hqepcss.glsl's pnHqepcssDefaults), shared
// with the runner (the `hqepcss` technique's settings,
// runner/pipeline/pcss_settings.cpp). Valid as GLSL and as C++: only
// comments and guarded #defines.

#ifndef PENUMBRA_HQEPCSS_H
#define PENUMBRA_HQEPCSS_H

// Refinements of the search region from the pyramid's exact square min.
#define PN_HQEPCSS_REFINE_ITERATIONS 8
// Blocker-search nodes of this side or smaller are estimated at their min.
#define PN_HQEPCSS_LEAF_SIDE 8

#endif  // PENUMBRA_HQEPCSS_H
