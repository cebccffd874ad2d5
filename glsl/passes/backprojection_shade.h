// backprojection_shade.h — what passes/backprojection_shade.comp / .frag and
// their runner side (runner/technique/backprojection_technique.cpp) share.
// Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_BACKPROJECTION_SHADE_H
#define PENUMBRA_PASSES_BACKPROJECTION_SHADE_H

#include "light_fields.h"
#include "uniform_block.h"

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_BACKPROJECTION_SHADE_MIP_BINDING 0        // sampler2D: the map's aligned min/max mip chain
#define PN_BACKPROJECTION_SHADE_GBUFFER_BINDING 1    // sampler2D, RGBA32F: (u, v, light depth, surface)
#define PN_BACKPROJECTION_SHADE_VISIBILITY_IMAGE 2   // image2D, r32f
#define PN_BACKPROJECTION_SHADE_PARAMS_BINDING 3
#define PN_BACKPROJECTION_SHADE_LAYER_BINDING 4      // sampler2D: the second layer's min/max chain (PN_BACKPROJECTION_SHADE_SLABS)
#define PN_BACKPROJECTION_SHADE_MAP_BINDING 5        // sampler2D: the shadow map the chain is of
#define PN_BACKPROJECTION_SHADE_LAYER_MAP_BINDING 6  // sampler2D: the second layer's map (PN_BACKPROJECTION_SHADE_SLABS)

PN_UNIFORM_BLOCK(PnBackprojectionShadeParams, PN_BACKPROJECTION_SHADE_PARAMS_BINDING)
  PN_LIGHT_FIELDS   // PnLight (light_model.glsl)
  float bias;       // light-depth units
  int side;         // side × side light samples
  float tolerance;  // a node of depth range <= tolerance · (dP - min) stands as one patch
  int budget;       // nodes a pixel
  float gap;        // texel widths: the depth step neighbours of one surface may take
  float thickness;  // a silhouette's wall: its share of the way from the occluder to the receiver
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_BACKPROJECTION_SHADE_H
