// sample_table_query.h — what passes/sample_table_query.comp and its runner
// side (runner/check/sample_table_check.cpp) share: binding points. Valid as
// GLSL and as C++.

#ifndef PENUMBRA_PASSES_SAMPLE_TABLE_QUERY_H
#define PENUMBRA_PASSES_SAMPLE_TABLE_QUERY_H

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_SAMPLE_TABLE_QUERY_QUERIES_BINDING 0  // sampler2D, RGBA32F: pixel x, y, region side, i
#define PN_SAMPLE_TABLE_QUERY_TABLE_BINDING 1    // sampler2D, RG32F (sample_table.glsl)
#define PN_SAMPLE_TABLE_QUERY_RESULT_A_BINDING 2 // image2D, rgba32f: k, first column, last column, set
#define PN_SAMPLE_TABLE_QUERY_RESULT_B_BINDING 3 // image2D, rgba32f: column, texel x, y, 0

#endif  // PENUMBRA_PASSES_SAMPLE_TABLE_QUERY_H
