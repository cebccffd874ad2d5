// depth_pyramid_bindings.h — what passes/depth_pyramid_build.comp, depth_pyramid_query.comp
// and their runner side (runner/pass_runners/depth_pyramid_pass.cpp) share. Valid as
// GLSL and as C++ (uniform_block.h).

#ifndef PENUMBRA_PASSES_DEPTH_PYRAMID_H
#define PENUMBRA_PASSES_DEPTH_PYRAMID_H

#include "uniform_block.h"

// depth_pyramid_build.comp: level 0 from the map, level i from layer i − 1 of
// the pyramid itself (read through the sampler, written through the image).
#define PN_PYRAMID_BUILD_MAP_BINDING 0    // sampler2D, R32F, N×N
#define PN_PYRAMID_BUILD_READ_BINDING 1   // sampler2DArray, RGBA32F: the pyramid
#define PN_PYRAMID_BUILD_WRITE_IMAGE 2    // image2DArray, rgba32f, layered: the same texture
#define PN_PYRAMID_BUILD_PARAMS_BINDING 3
#define PN_PYRAMID_BUILD_TEXELS_BINDING 4  // storage buffer: the texels of an incremental update (texel_list.glsl)

PN_UNIFORM_BLOCK(PnPyramidBuildParams, PN_PYRAMID_BUILD_PARAMS_BINDING)
  int level;
  int texelFirst;  // texelCount > 0: one invocation per listed texel, from texelFirst
  int texelCount;  // 0: the dispatch's grid covers the whole level
PN_END_UNIFORM_BLOCK(pnParams)

// depth_pyramid_query.comp: query k is texel k of the query image, (u, v, side, unused).
#define PN_PYRAMID_QUERY_PYRAMID_BINDING 0  // sampler2DArray
#define PN_PYRAMID_QUERY_QUERIES_BINDING 1  // sampler2D, RGBA32F
#define PN_PYRAMID_QUERY_RESULTS_IMAGE 2    // image2D, rgba32f: (min, max, 0, 0)

#endif  // PENUMBRA_PASSES_DEPTH_PYRAMID_H
