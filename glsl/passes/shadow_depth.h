// shadow_depth.h — what passes/shadow_depth.vert, shadow_depth.frag and their
// runner side (runner/pass_runners/shadow_map_pass.cpp) share: the parameter block,
// its binding and the varying between the stages. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_SHADOW_DEPTH_H
#define PENUMBRA_PASSES_SHADOW_DEPTH_H

#include "scene_raster.h"
#include "uniform_block.h"

#define PN_SHADOW_DEPTH_PARAMS_BINDING 0
#define PN_SHADOW_DEPTH_LINEAR_DEPTH_LOCATION 0  // vertex -> fragment: float, linear light depth

PN_UNIFORM_BLOCK(PnShadowDepthParams, PN_SHADOW_DEPTH_PARAMS_BINDING)
  mat4 lightView;
  mat4 lightProjection;
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_SHADOW_DEPTH_H
