// blur.h — what passes/blur.comp and its runner side (runner/passes/blur_pass.cpp)
// share: binding points and the parameter block. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_BLUR_H
#define PENUMBRA_PASSES_BLUR_H

#include "uniform_block.h"

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_BLUR_SOURCE_BINDING 0  // sampler2D, R32F
#define PN_BLUR_DEPTH_BINDING 1   // sampler2D, R32F (depth-aware variant)
#define PN_BLUR_TARGET_BINDING 2  // image2D, r32f
#define PN_BLUR_PARAMS_BINDING 3

PN_UNIFORM_BLOCK(PnBlurPassParams, PN_BLUR_PARAMS_BINDING)
  ivec2 axis;
  int radius;
  float sigma;
  int depthAware;  // 0: plain Gaussian, 1: depth-aware
  float depthTolerance;
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_BLUR_H
