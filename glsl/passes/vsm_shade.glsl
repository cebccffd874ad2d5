// vsm_shade.glsl — the vsm and evsm techniques' visibility: per screen pixel,
// its G-buffer entry (u, v in shadow-map texels, light depth, valid) read
// against the blurred moments and the depth pyramid with vsm.glsl. A pixel
// that sees no surface (valid 0, or a non-finite depth) is lit.
//   bindings and parameter block: vsm_shade.h
//
// options:
//   PN_VSM_SHADE_KIND   PN_VSM_KIND_VSM (default), _EVSM2 or _EVSM4; the
//   runner compiles one program per kind.
//
// The body of the compute pass and the fragment shader (shade_pass.h):
// pnShade(p), the visibility of screen pixel p.

#ifndef PENUMBRA_PASSES_VSM_SHADE_GLSL
#define PENUMBRA_PASSES_VSM_SHADE_GLSL

#include "vsm_shade.h"

#ifndef PN_VSM_SHADE_KIND
#define PN_VSM_SHADE_KIND PN_VSM_KIND_VSM
#endif

layout(binding = PN_VSM_SHADE_MOMENTS_BINDING) uniform sampler2D pnMoments;
layout(binding = PN_VSM_SHADE_PYRAMID_BINDING) uniform sampler2DArray pnPyramid;
layout(binding = PN_VSM_SHADE_GBUFFER_BINDING) uniform sampler2D pnGBuffer;

#include "vsm.glsl"

float pnShade(ivec2 p) {
  vec4 g = texelFetch(pnGBuffer, p, 0);
  float v = 1.0;
  if (g.w != 0.0) {
#if PN_VSM_SHADE_KIND == PN_VSM_KIND_EVSM4
    v = pnEvsm4(pnMoments, pnPyramid, g.xyz, pnParams.radius, pnParams.bias, pnParams.depthRange, pnParams.exponents,
                pnParams.minVariance, pnParams.bleedingReduction);
#elif PN_VSM_SHADE_KIND == PN_VSM_KIND_EVSM2
    v = pnEvsm2(pnMoments, pnPyramid, g.xyz, pnParams.radius, pnParams.bias, pnParams.depthRange,
                pnParams.exponents.x, pnParams.minVariance, pnParams.bleedingReduction);
#else
    v = pnVsm(pnMoments, pnPyramid, g.xyz, pnParams.radius, pnParams.bias, pnParams.minVariance,
              pnParams.bleedingReduction);
#endif
  }
  return v;
}

#endif  // PENUMBRA_PASSES_VSM_SHADE_GLSL
