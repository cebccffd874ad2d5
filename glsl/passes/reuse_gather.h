// reuse_gather.h — what passes/reuse_gather.comp and its runner side
// (runner/pass_runners/reuse_pass.cpp, ReusePass::gather) share: binding points and
// the parameter block. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_REUSE_GATHER_H
#define PENUMBRA_PASSES_REUSE_GATHER_H

#include "uniform_block.h"

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_REUSE_GATHER_PARENTS_BINDING 0  // sampler2D, R32F: parent codes (reuse_link.comp)
#define PN_REUSE_GATHER_VALUES_BINDING 1   // sampler2D, R32F
#define PN_REUSE_GATHER_RESULT_BINDING 2   // image2D, rgba32f: representative x, y, its value, 0
#define PN_REUSE_GATHER_PARAMS_BINDING 3

PN_UNIFORM_BLOCK(PnReuseGatherParams, PN_REUSE_GATHER_PARAMS_BINDING)
  int tile;
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_REUSE_GATHER_H
