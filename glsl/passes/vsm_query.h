// vsm_query.h — what passes/vsm_query.comp and its runner side
// (runner/pass_runners/vsm_pass.cpp) share: binding points and the parameter block.
// Valid as GLSL and as C++ (uniform_block.h).

#ifndef PENUMBRA_PASSES_VSM_QUERY_H
#define PENUMBRA_PASSES_VSM_QUERY_H

#include "uniform_block.h"
#include "vsm.h"  // glsl/vsm.h: PN_VSM_KIND_*, PN_VSM_BOUND_*

// Query k is texel k of the query image, (texel x, texel y, receiver depth, bias); result k is
// (visibility, Chebyshev bound p, p after the bleeding reduction, depth-range bound code PN_VSM_BOUND_*).
#define PN_VSM_QUERY_MOMENTS_BINDING 0   // sampler2D, RG32F or RGBA32F: the blurred moments
#define PN_VSM_QUERY_PYRAMID_BINDING 1   // sampler2DArray, RGBA32F: the depth pyramid of the map
#define PN_VSM_QUERY_QUERIES_BINDING 2   // sampler2D, RGBA32F
#define PN_VSM_QUERY_RESULTS_IMAGE 3     // image2D, rgba32f
#define PN_VSM_QUERY_PARAMS_BINDING 4

PN_UNIFORM_BLOCK(PnVsmQueryParams, PN_VSM_QUERY_PARAMS_BINDING)
  vec2 depthRange;  // EVSM (near, far)
  vec2 exponents;   // EVSM (c+, c-)
  int kind;         // PN_VSM_KIND_*
  int radius;       // the blur's radius: the depth-range bound's window is 2 radius + 1 wide
  float minVariance;
  float bleedingReduction;
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_VSM_QUERY_H
