// summed_area_query.h — what passes/summed_area_query.comp and its runner side
// (runner/pass_runners/summed_area_pass.cpp) share. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_SUMMED_AREA_QUERY_H
#define PENUMBRA_PASSES_SUMMED_AREA_QUERY_H

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_SUMMED_AREA_QUERY_TABLE_BINDING 0  // usampler2D, RGBA32UI: the summed-area table
#define PN_SUMMED_AREA_QUERY_RECTS_BINDING 1  // sampler2D, RGBA32F: (origin x, y, width, height)
#define PN_SUMMED_AREA_QUERY_FIXED_IMAGE 2    // uimage2D, rgba32ui: (sum low word, high word, finite, texels)
#define PN_SUMMED_AREA_QUERY_FLOAT_IMAGE 3    // image2D, rgba32f: (sum, mean, finite, texels)

#endif  // PENUMBRA_PASSES_SUMMED_AREA_QUERY_H
