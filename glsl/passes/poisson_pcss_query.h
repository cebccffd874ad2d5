// poisson_pcss_query.h — what passes/poisson_pcss_query.comp and its runner
// side (runner/pass_runners/poisson_pcss_pass.cpp) share. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_POISSON_PCSS_QUERY_H
#define PENUMBRA_PASSES_POISSON_PCSS_QUERY_H

#include "uniform_block.h"
#include "../poisson_pcss.h"

#define PN_POISSON_QUERY_MAP_BINDING 0   // sampler2D, R32F: the depth map
#define PN_POISSON_QUERY_A_BINDING 1     // sampler2D, RGBA32F: (centre x, y, diameter, receiver depth)
#define PN_POISSON_QUERY_B_BINDING 2     // sampler2D, RGBA32F: (bias, sample count, rotation cos, sin)
#define PN_POISSON_QUERY_RESULT_IMAGE 3  // image2D, rgba32f: (occluders, depth sum, samples, 0)
#define PN_POISSON_QUERY_PARAMS_BINDING 4

// A disk, read in place (pnPoissonOcclusionDisk) when the pass is compiled with
// PN_QUERY_DISK_IN_BLOCK.
PN_UNIFORM_BLOCK(PnPoissonQueryParams, PN_POISSON_QUERY_PARAMS_BINDING)
  PN_VEC2_ARRAY(points, PN_POISSON_MAX_SAMPLES)
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_POISSON_PCSS_QUERY_H
