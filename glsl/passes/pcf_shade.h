// pcf_shade.h — what passes/pcf_shade.comp and its runner side
// (runner/technique/pcf_technique.cpp) share. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_PCF_SHADE_H
#define PENUMBRA_PASSES_PCF_SHADE_H

#include "light_fields.h"
#include "uniform_block.h"

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_PCF_SHADE_MAP_BINDING 0        // sampler2D, R32F: the shadow map (linear light depth)
#define PN_PCF_SHADE_GBUFFER_BINDING 1    // sampler2D, RGBA32F: (u, v, light depth, surface)
#define PN_PCF_SHADE_VISIBILITY_IMAGE 2   // image2D, r32f
#define PN_PCF_SHADE_PARAMS_BINDING 3

PN_UNIFORM_BLOCK(PnPcfShadeParams, PN_PCF_SHADE_PARAMS_BINDING)
  PN_LIGHT_FIELDS          // PnLight (light_model.glsl): the receiver plane's slope clamp
  float bias;              // light-depth units
  float receiverPlaneTan;  // > 0: a receiver plane from the G-buffer, slopes clamped to this tangent; 0: none
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_PCF_SHADE_H
