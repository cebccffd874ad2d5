// surface.h — what passes/surface.vert, surface.frag and their runner side
// (runner/pass_runners/surface_pass.cpp) share: the parameter block, its binding
// and the varying between the stages. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_SURFACE_H
#define PENUMBRA_PASSES_SURFACE_H

#include "scene_raster.h"
#include "uniform_block.h"

#define PN_SURFACE_PARAMS_BINDING 0
#define PN_SURFACE_WORLD_LOCATION 0  // vertex -> fragment: vec3, world position

PN_UNIFORM_BLOCK(PnSurfaceParams, PN_SURFACE_PARAMS_BINDING)
  mat4 cameraViewProjection;
  vec4 cameraPosition;  // xyz: world
  vec4 lightPosition;   // homogeneous: (the area light's centre, 1), or (the direction towards the sun, 0)
  vec4 groundLo;        // xyz: the ground slab's box
  vec4 groundHi;
  vec4 groundAlbedo;    // rgb
  vec4 boxAlbedo;       // rgb
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_SURFACE_H
