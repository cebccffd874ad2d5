// shadow_depth.h — what passes/shadow_depth.vert, shadow_depth.frag, the second
// layer's shadow_depth_peel.frag and shadow_depth_back.frag and their runner side
// (runner/pass_runners/shadow_map_pass.cpp, second_layer_pass.cpp) share: the
// parameter block, the bindings and the varying between the stages. Valid as
// GLSL and as C++.

#ifndef PENUMBRA_PASSES_SHADOW_DEPTH_H
#define PENUMBRA_PASSES_SHADOW_DEPTH_H

#include "scene_raster.h"
#include "uniform_block.h"

#define PN_SHADOW_DEPTH_PARAMS_BINDING 0
#define PN_SHADOW_DEPTH_LINEAR_DEPTH_LOCATION 0  // vertex -> fragment: float, linear light depth
#define PN_SHADOW_DEPTH_FIRST_LAYER_BINDING 1    // shadow_depth_peel.frag: sampler2D, the map (the first layer)

// Depth peeling's margin (shadow_depth_peel.frag): a surface is behind the first layer when its
// depth passes the first's by more than this share of it — the same triangle drawn twice, or two
// faces that touch (a box on the ground), are not a second layer.
#define PN_SHADOW_DEPTH_PEEL_MARGIN 1e-4

PN_UNIFORM_BLOCK(PnShadowDepthParams, PN_SHADOW_DEPTH_PARAMS_BINDING)
  mat4 lightView;
  mat4 lightProjection;
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_SHADOW_DEPTH_H
