// blur_bindings.h — what passes/blur.comp and its runner side (runner/pass_runners/blur_pass.cpp)
// share: binding points and the parameter block. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_BLUR_H
#define PENUMBRA_PASSES_BLUR_H

#include "uniform_block.h"

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_BLUR_SOURCE_BINDING 0      // sampler2D, R32F, RG32F or RGBA32F (the pass's channel count)
#define PN_BLUR_DEPTH_BINDING 1       // sampler2D, R32F (depth-aware variant)
#define PN_BLUR_TARGET_BINDING 2      // image2D, r32f, rg32f or rgba32f (PN_BLUR_PASS_CHANNELS)
#define PN_BLUR_PARAMS_BINDING 3
#define PN_BLUR_FILTER_MAP_BINDING 4  // sampler2D, RGBA32F (adaptive radius): the filter-region map, .w = side

PN_UNIFORM_BLOCK(PnBlurPassParams, PN_BLUR_PARAMS_BINDING)
  ivec2 axis;
  int radius;
  float sigma;
  int depthAware;  // 0: plain Gaussian, 1: depth-aware
  float depthTolerance;
  int adaptive;          // 0: radius everywhere, 1: per-pixel radius from the filter map
  float pixelsPerTexel;  // adaptive: screen pixels per shadow-map texel
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_BLUR_H
