// backprojection_shade.glsl — the back-projection soft shadow per screen pixel
// (technique `backprojection`): backprojection.glsl's pnBackprojection at the
// pixel's G-buffer position and light depth. Pixels that see no surface are
// lit. Bindings and the block: backprojection_shade.h.
//
// The body of the compute pass and the fragment shader (shade_pass.h):
// pnShade(p), the visibility of screen pixel p. Defined PN_BACKPROJECTION_SHADE_SLABS:
// the call with the map's second layer (issue 42), every texel a slab.
// Defined PN_BACKPROJECTION_ENGINE_FORM (the runner's rows whose settings are the defaults but
// the bias): pnBackprojectionDefaults, the settings as compile-time constants — the program an
// engine's shader makes, which bench times (docs/benchmarks.md).

#ifndef PENUMBRA_PASSES_BACKPROJECTION_SHADE_GLSL
#define PENUMBRA_PASSES_BACKPROJECTION_SHADE_GLSL

#include "backprojection_shade.h"

layout(binding = PN_BACKPROJECTION_SHADE_MIP_BINDING) uniform sampler2D pnMip;
layout(binding = PN_BACKPROJECTION_SHADE_MAP_BINDING) uniform sampler2D pnShadowMap;
layout(binding = PN_BACKPROJECTION_SHADE_GBUFFER_BINDING) uniform sampler2D pnGBuffer;
#ifdef PN_BACKPROJECTION_SHADE_SLABS
layout(binding = PN_BACKPROJECTION_SHADE_LAYER_BINDING) uniform sampler2D pnSecondMip;
layout(binding = PN_BACKPROJECTION_SHADE_LAYER_MAP_BINDING) uniform sampler2D pnSecondMap;
#endif

#include "backprojection.glsl"

float pnShade(ivec2 p) {
  vec4 receiver = texelFetch(pnGBuffer, p, 0);
  if (receiver.w == 0.0) return 1.0;
#ifdef PN_BACKPROJECTION_ENGINE_FORM  // the row's settings are the defaults: constants, as an engine compiles them
  PnBackprojectionSettings s = pnBackprojectionDefaults(pnParams.bias);
#else
  PnBackprojectionSettings s = PnBackprojectionSettings(pnParams.bias, pnParams.side, pnParams.tolerance,
                                                        pnParams.budget, pnParams.gap, pnParams.thickness);
#endif
#ifdef PN_BACKPROJECTION_SHADE_SLABS
  return pnBackprojection(pnShadowMap, pnMip, pnSecondMap, pnSecondMip, PN_LIGHT_FROM_FIELDS(pnParams), receiver.xyz, s);
#else
  return pnBackprojection(pnShadowMap, pnMip, PN_LIGHT_FROM_FIELDS(pnParams), receiver.xyz, s);
#endif
}

#endif  // PENUMBRA_PASSES_BACKPROJECTION_SHADE_GLSL
