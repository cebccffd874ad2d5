// savsm_shade.glsl — the savsm technique's visibility: per screen pixel, its
// G-buffer entry (u, v in shadow-map texels, light depth, valid) through
// savsm.glsl against the moments table and the min/max mip chain. A pixel that
// sees no surface is lit.
//   bindings and parameter block: savsm_params.h
//
// options:
//   PN_SAVSM_TABLE   PN_SAVSM_TABLE_FIXED (default) or _FLOAT: the table's
//   kind and sampler type; the runner compiles one program per kind.
//   PN_SAVSM_ENGINE_FORM   defined for the runner's rows whose settings are the defaults but the
//   bias: pnSavsmDefaults, compile-time constants — the program an engine's shader makes.
//
// The body of the compute pass and the fragment shader (shade_pass.h):
// pnShade(p), the visibility of screen pixel p.

#ifndef PENUMBRA_PASSES_SAVSM_SHADE_GLSL
#define PENUMBRA_PASSES_SAVSM_SHADE_GLSL

#include "savsm_params.h"
#include "savsm.glsl"

layout(binding = PN_SAVSM_TABLE_BINDING) uniform PN_SAVSM_TABLE_SAMPLER pnTable;
layout(binding = PN_SAVSM_MIP_BINDING) uniform sampler2D pnMip;
layout(binding = PN_SAVSM_INPUT_BINDING) uniform sampler2D pnGBuffer;

#include "savsm_params.glsl"

float pnShade(ivec2 p) {
  vec4 g = texelFetch(pnGBuffer, p, 0);
  float v = 1.0;
  if (g.w != 0.0) {
#ifdef PN_SAVSM_ENGINE_FORM  // the row's settings are the defaults: constants, as an engine compiles them
    PnSavsmSettings s = pnSavsmDefaults(pnParams.bias);
#else
    PnSavsmSettings s = pnSavsmParamsSettings();
#endif
    v = pnSavsm(pnTable, pnMip, pnSavsmParamsLight(), g.xyz, pnParams.unitRange, s);
  }
  return v;
}

#endif  // PENUMBRA_PASSES_SAVSM_SHADE_GLSL
