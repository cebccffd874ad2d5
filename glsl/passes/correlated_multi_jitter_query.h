// correlated_multi_jitter_query.h — what
// passes/correlated_multi_jitter_query.comp and its runner side
// (runner/check/sample_table_check.cpp) share: binding points. Valid as GLSL
// and as C++.

#ifndef PENUMBRA_PASSES_CORRELATED_MULTI_JITTER_QUERY_H
#define PENUMBRA_PASSES_CORRELATED_MULTI_JITTER_QUERY_H

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_CMJ_QUERY_QUERIES_BINDING 0  // sampler2D, RGBA32F: group k, sample index, set, seed
#define PN_CMJ_QUERY_RESULTS_BINDING 2  // image2D, rgba32f: x, y, 0, 0

#endif  // PENUMBRA_PASSES_CORRELATED_MULTI_JITTER_QUERY_H
