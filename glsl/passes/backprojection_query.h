// backprojection_query.h — what passes/backprojection_query.comp and its runner
// side (runner/pass_runners/backprojection_pass.cpp) share. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_BACKPROJECTION_QUERY_H
#define PENUMBRA_PASSES_BACKPROJECTION_QUERY_H

#include "light_fields.h"
#include "uniform_block.h"

#define PN_BACKPROJECTION_QUERY_RESULT_IMAGE 0  // image2D, rgba32f: (visibility, blocked, nodes, patches)
#define PN_BACKPROJECTION_QUERY_MIP_BINDING 1   // sampler2D: the aligned min/max mip chain
#define PN_BACKPROJECTION_QUERY_A_BINDING 2     // sampler2D, RGBA32F: receiver (u, v, d, bias)
#define PN_BACKPROJECTION_QUERY_B_BINDING 3     // sampler2D, RGBA32F: (side, tolerance, budget, gap)
#define PN_BACKPROJECTION_QUERY_PARAMS_BINDING 4
#define PN_BACKPROJECTION_QUERY_C_BINDING 5     // sampler2D, RGBA32F: (thickness, slabs (1: the second layer's call), -, -)
#define PN_BACKPROJECTION_QUERY_LAYER_BINDING 6  // sampler2D: the second layer's min/max chain (any texture when no query reads it)
#define PN_BACKPROJECTION_QUERY_MAP_BINDING 7    // sampler2D: the map the chain is of
#define PN_BACKPROJECTION_QUERY_LAYER_MAP_BINDING 8  // sampler2D: the second layer's map (as its chain)

PN_UNIFORM_BLOCK(PnBackprojectionQueryParams, PN_BACKPROJECTION_QUERY_PARAMS_BINDING)
  PN_LIGHT_FIELDS  // PnLight (light_model.glsl)
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_BACKPROJECTION_QUERY_H
