// reuse_link.h — what passes/reuse_link.comp and its runner side
// (runner/pass_runners/reuse_pass.cpp, ReusePass::link) share: binding points and
// the parameter block. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_REUSE_LINK_H
#define PENUMBRA_PASSES_REUSE_LINK_H

#include "uniform_block.h"

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_REUSE_LINK_ENTRIES_BINDING 0  // sampler2D, RGBA32F: d, x, y, s
#define PN_REUSE_LINK_PARENTS_BINDING 2  // image2D, r32f: parent codes PN_REUSE_* (reuse.h)
#define PN_REUSE_LINK_PARAMS_BINDING 3

PN_UNIFORM_BLOCK(PnReuseParams, PN_REUSE_LINK_PARAMS_BINDING)
  float sigma1;
  float sigma2;
  float sigma3;
  int tile;
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_REUSE_LINK_H
