// vsm_moments.h — what passes/vsm_moments.comp and its runner side
// (runner/pass_runners/vsm_pass.cpp) share: binding points and the parameter block.
// Valid as GLSL and as C++ (uniform_block.h). The moment kinds PN_VSM_KIND_*
// are the module's (glsl/vsm.h).

#ifndef PENUMBRA_PASSES_VSM_MOMENTS_H
#define PENUMBRA_PASSES_VSM_MOMENTS_H

#include "uniform_block.h"
#include "vsm.h"  // glsl/vsm.h: PN_VSM_KIND_*

// The kind is the pass's PN_VSM_MOMENTS_KIND (a compile-time switch: it fixes the target's format).
#define PN_VSM_MOMENTS_MAP_BINDING 0     // sampler2D, R32F: linear depth, N×N
#define PN_VSM_MOMENTS_TARGET_BINDING 1  // image2D, rg32f (VSM, EVSM-2) or rgba32f (EVSM-4)
#define PN_VSM_MOMENTS_PARAMS_BINDING 2

PN_UNIFORM_BLOCK(PnVsmMomentsParams, PN_VSM_MOMENTS_PARAMS_BINDING)
  vec2 depthRange;  // (near, far): VSM's depth of non-finite texels is .y; EVSM normalises by both
  vec2 exponents;   // EVSM (c+, c-)
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_VSM_MOMENTS_H
