// depth_cache.h — what passes/depth_cache_compose.comp, depth_cache_query.comp
// and their runner side (runner/pass_runners/depth_cache_pass.cpp) share: bindings
// and parameter blocks. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_DEPTH_CACHE_H
#define PENUMBRA_PASSES_DEPTH_CACHE_H

#include "uniform_block.h"

// Both passes: the two maps of depth_cache.glsl.
#define PN_DEPTH_CACHE_STATIC_BINDING 0   // sampler2D, R32F
#define PN_DEPTH_CACHE_DYNAMIC_BINDING 1  // sampler2D, R32F

// depth_cache_compose.comp: the composition written over the whole composed map or its listed texels.
#define PN_DEPTH_CACHE_COMPOSED_IMAGE 2   // image2D, r32f
#define PN_DEPTH_CACHE_COMPOSE_PARAMS_BINDING 3
#define PN_DEPTH_CACHE_TEXELS_BINDING 6    // storage buffer: the texels (texel_list.glsl)

PN_UNIFORM_BLOCK(PnDepthCacheComposeParams, PN_DEPTH_CACHE_COMPOSE_PARAMS_BINDING)
  int texelFirst;  // texelCount > 0: one invocation per listed texel, from texelFirst
  int texelCount;  // 0: the dispatch's grid covers the whole map
PN_END_UNIFORM_BLOCK(pnParams)

// depth_cache_query.comp: query k is texel k of the query image, (u, v, receiver depth, bias), u and v
// integral texels; result k is (composed depth, visibility, 0, 0).
#define PN_DEPTH_CACHE_QUERIES_BINDING 4  // sampler2D, RGBA32F
#define PN_DEPTH_CACHE_RESULTS_IMAGE 5    // image2D, rgba32f

#endif  // PENUMBRA_PASSES_DEPTH_CACHE_H
