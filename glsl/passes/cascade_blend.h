// cascade_blend.h — what passes/cascade_blend.comp and its runner side
// (runner/pass_runners/cascade_blend_pass.cpp) share: bindings and the parameter block.
// Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_CASCADE_BLEND_H
#define PENUMBRA_PASSES_CASCADE_BLEND_H

#include "uniform_block.h"

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_CASCADE_BLEND_VIEW_DEPTH_BINDING 0  // sampler2D, RGBA32F: the camera's G-buffer (z: view depth, w: surface)
#define PN_CASCADE_BLEND_VISIBILITY0_BINDING 1  // sampler2D, R32F: cascade 0's visibility (screen-sized)
#define PN_CASCADE_BLEND_VISIBILITY1_BINDING 2
#define PN_CASCADE_BLEND_VISIBILITY2_BINDING 3
#define PN_CASCADE_BLEND_VISIBILITY3_BINDING 4
#define PN_CASCADE_BLEND_TARGET_BINDING 5       // image2D, r32f: the blended visibility
#define PN_CASCADE_BLEND_PARAMS_BINDING 6

PN_UNIFORM_BLOCK(PnCascadeBlendParams, PN_CASCADE_BLEND_PARAMS_BINDING)
  vec4 splitFar;  // C_1 ... C_m
  float near;     // C_0
  int count;      // m
  float band;
  int fadeLast;
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_CASCADE_BLEND_H
