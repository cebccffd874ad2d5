// vsm_shade.h — what passes/vsm_shade.comp and its runner side
// (runner/pass_runners/vsm_pass.cpp, the vsm and evsm techniques) share: binding
// points and the parameter block. Valid as GLSL and as C++ (uniform_block.h).

#ifndef PENUMBRA_PASSES_VSM_SHADE_H
#define PENUMBRA_PASSES_VSM_SHADE_H

#include "uniform_block.h"
#include "vsm.h"  // glsl/vsm.h: PN_VSM_KIND_*

// The kind is the pass's PN_VSM_SHADE_KIND (one program per kind).
#define PN_VSM_SHADE_MOMENTS_BINDING 0     // sampler2D, RG32F or RGBA32F: the blurred moments, N×N
#define PN_VSM_SHADE_PYRAMID_BINDING 1     // sampler2DArray, RGBA32F: the depth pyramid of the map
#define PN_VSM_SHADE_GBUFFER_BINDING 2     // sampler2D, RGBA32F: (u, v in texels, light depth, valid)
#define PN_VSM_SHADE_VISIBILITY_IMAGE 3    // image2D, r32f: 1 lit, 0 in shadow
#define PN_VSM_SHADE_PARAMS_BINDING 4

PN_UNIFORM_BLOCK(PnVsmShadeParams, PN_VSM_SHADE_PARAMS_BINDING)
  vec2 depthRange;  // EVSM (near, far)
  vec2 exponents;   // EVSM (c+, c-)
  int radius;       // the blur's radius: the depth-range bound's window
  float bias;
  float minVariance;
  float bleedingReduction;
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_VSM_SHADE_H
