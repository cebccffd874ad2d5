// light_model_query.h — what passes/light_model_query.comp and its runner
// side (runner/check/light_model_check.cpp) share: binding points and the
// light's parameter block. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_LIGHT_MODEL_QUERY_H
#define PENUMBRA_PASSES_LIGHT_MODEL_QUERY_H

#include "light_fields.h"
#include "uniform_block.h"

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_LIGHT_MODEL_QUERY_QUERIES_BINDING 0  // sampler2D, RGBA32F: receiver depth, blocker depth, -, -
#define PN_LIGHT_MODEL_QUERY_RESULTS_BINDING 2  // image2D, rgba32f: the four widths
#define PN_LIGHT_MODEL_QUERY_PARAMS_BINDING 3

// The fields of light_model.glsl's PnLight.
PN_UNIFORM_BLOCK(PnLightParams, PN_LIGHT_MODEL_QUERY_PARAMS_BINDING)
  PN_LIGHT_FIELDS
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_LIGHT_MODEL_QUERY_H
