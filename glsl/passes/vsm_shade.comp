// vsm_shade.comp — the vsm and evsm techniques' visibility: per screen pixel,
// its G-buffer entry (u, v in shadow-map texels, light depth, valid) read
// against the blurred moments and the depth pyramid with vsm.glsl. A pixel
// that sees no surface (valid 0, or a non-finite depth) is lit.
//   bindings and parameter block: vsm_shade.h
//
// options:
//   PN_VSM_SHADE_KIND   PN_VSM_KIND_VSM (default), _EVSM2 or _EVSM4; the
//   runner compiles one program per kind.

layout(local_size_x = 8, local_size_y = 8) in;

#include "vsm_shade.h"

#ifndef PN_VSM_SHADE_KIND
#define PN_VSM_SHADE_KIND PN_VSM_KIND_VSM
#endif

layout(binding = PN_VSM_SHADE_MOMENTS_BINDING) uniform sampler2D pnMoments;
layout(binding = PN_VSM_SHADE_PYRAMID_BINDING) uniform sampler2DArray pnPyramid;
layout(binding = PN_VSM_SHADE_GBUFFER_BINDING) uniform sampler2D pnGBuffer;
layout(r32f, binding = PN_VSM_SHADE_VISIBILITY_IMAGE) writeonly uniform image2D pnVisibility;

#include "vsm.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnVisibility)))) return;
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
  imageStore(pnVisibility, p, vec4(v, 0.0, 0.0, 0.0));
}
