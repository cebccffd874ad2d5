// region_query.h — what passes/region_query.comp and its runner side
// (runner/pass_runners/region_pass.cpp) share: binding points and the parameter
// block. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_REGION_QUERY_H
#define PENUMBRA_PASSES_REGION_QUERY_H

#include "uniform_block.h"

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_REGION_QUERY_QUERIES_BINDING 0  // sampler2D, RGBA32F: (x, y, side, -); with areas: (x, y, side, texel)
#define PN_REGION_QUERY_RESULTS_BINDING 2  // image2D, rgba32f: (origin x, y, side, level); with areas: below
#define PN_REGION_QUERY_PARAMS_BINDING 3

PN_UNIFORM_BLOCK(PnRegionQueryParams, PN_REGION_QUERY_PARAMS_BINDING)
  int mapSize;
  int centred;  // 0: literal Steps 1–7, 1: centred variant
  int areas;    // 1: the area-weighted region instead (region_query.comp)
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_REGION_QUERY_H
