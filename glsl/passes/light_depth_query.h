// light_depth_query.h — what passes/light_depth_query.comp and its runner side
// (runner/pass_runners/light_depth_query_pass.cpp) share: binding points and the
// projection block. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_LIGHT_DEPTH_QUERY_H
#define PENUMBRA_PASSES_LIGHT_DEPTH_QUERY_H

#include "uniform_block.h"

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_LIGHT_DEPTH_QUERY_QUERIES_BINDING 0  // sampler2D, RGBA32F: depth-buffer value, world x, y, z
#define PN_LIGHT_DEPTH_QUERY_RESULTS_BINDING 1  // image2D, rgba32f: linear depth ([-1, 1] clip), ([0, 1] clip), u, v
#define PN_LIGHT_DEPTH_QUERY_PARAMS_BINDING 2

PN_UNIFORM_BLOCK(PnLightDepthParams, PN_LIGHT_DEPTH_QUERY_PARAMS_BINDING)
  mat4 lightProjection;
  mat4 lightView;  // pnLightProject's
  float mapSize;
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_LIGHT_DEPTH_QUERY_H
