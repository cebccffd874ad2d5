// gbuffer.h — what passes/gbuffer.vert, gbuffer.frag and their runner side
// (runner/pass_runners/gbuffer_pass.cpp) share: the parameter block, its binding
// and the varying between the stages. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_GBUFFER_H
#define PENUMBRA_PASSES_GBUFFER_H

#include "scene_raster.h"
#include "light_fields.h"
#include "uniform_block.h"

#define PN_GBUFFER_PARAMS_BINDING 0
#define PN_GBUFFER_WORLD_LOCATION 0  // vertex -> fragment: vec3, world position

PN_UNIFORM_BLOCK(PnGBufferParams, PN_GBUFFER_PARAMS_BINDING)
  mat4 cameraViewProjection;
  mat4 lightView;
  mat4 lightProjection;
  vec4 cameraPosition;  // xyz
  PN_LIGHT_FIELDS       // PnLight: a texel's world width at a depth (pnLightTexelWorld, light_model.glsl)
  float normalOffset;   // texels
  float viewDepthLo;      // the surfaces kept: camera view depth in [lo, hi) (0, +Inf: all)
  float viewDepthHi;
  vec4 viewDepthPlane;    // view depth = dot(plane, (world, 1))
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_GBUFFER_H
