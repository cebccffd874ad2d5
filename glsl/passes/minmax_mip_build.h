// minmax_mip_build.h — what passes/minmax_mip_build.comp and its runner side
// (runner/pass_runners/minmax_mip_pass.cpp) share: binding points and the
// parameter block. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_MINMAX_MIP_BUILD_H
#define PENUMBRA_PASSES_MINMAX_MIP_BUILD_H

#include "uniform_block.h"

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_MINMAX_MIP_SHADOW_MAP_BINDING 0  // sampler2D, R32F
#define PN_MINMAX_MIP_READ_BINDING 1        // sampler2D, RGBA32F (two nodes a texel), all levels: the chain (minmax_mip.glsl)
#define PN_MINMAX_MIP_WRITE_BINDING 2       // image2D, rgba32f: the chain at the level being written
#define PN_MINMAX_MIP_PARAMS_BINDING 3
#define PN_MINMAX_MIP_TEXELS_BINDING 4       // storage buffer: the texels of an incremental update (texel_list.glsl)

PN_UNIFORM_BLOCK(PnMipBuildParams, PN_MINMAX_MIP_PARAMS_BINDING)
  int level;
  int texelFirst;  // texelCount > 0: one invocation per listed texel, from texelFirst
  int texelCount;  // 0: the dispatch's grid covers the whole level
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_MINMAX_MIP_BUILD_H
