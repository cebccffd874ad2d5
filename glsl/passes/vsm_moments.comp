// vsm_moments.comp — the moments of vsm.glsl for every texel of a depth map:
// VSM (d, d^2), EVSM-2 (w+, w+^2) or EVSM-4 (w+, w+^2, w-, w-^2).
//   bindings and parameter block: vsm_moments.h
//
// options:
//   PN_VSM_MOMENTS_KIND   PN_VSM_KIND_VSM (default), _EVSM2 or _EVSM4: the
//   kind and with it the target's format (rg32f, rg32f, rgba32f); the runner
//   compiles one program per kind.

layout(local_size_x = 8, local_size_y = 8) in;

#include "vsm_moments.h"

#ifndef PN_VSM_MOMENTS_KIND
#define PN_VSM_MOMENTS_KIND PN_VSM_KIND_VSM
#endif

layout(binding = PN_VSM_MOMENTS_MAP_BINDING) uniform sampler2D pnDepthMap;
#if PN_VSM_MOMENTS_KIND == PN_VSM_KIND_EVSM4 || defined(GL_ES)  // ES 3.1 has no rg32f image format
layout(rgba32f, binding = PN_VSM_MOMENTS_TARGET_BINDING) writeonly uniform image2D pnMoments;
#else
layout(rg32f, binding = PN_VSM_MOMENTS_TARGET_BINDING) writeonly uniform image2D pnMoments;
#endif

#include "vsm.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnMoments)))) return;
  float d = texelFetch(pnDepthMap, p, 0).r;
#if PN_VSM_MOMENTS_KIND == PN_VSM_KIND_EVSM4
  vec4 m = pnEvsmMoments4(d, pnParams.depthRange, pnParams.exponents);
#elif PN_VSM_MOMENTS_KIND == PN_VSM_KIND_EVSM2
  vec4 m = vec4(pnEvsmMoments2(d, pnParams.depthRange, pnParams.exponents.x), 0.0, 0.0);
#else
  vec4 m = vec4(pnVsmMoments(d, pnParams.depthRange.y), 0.0, 0.0);
#endif
  imageStore(pnMoments, p, m);
}
