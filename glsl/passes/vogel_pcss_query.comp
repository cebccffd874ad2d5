// vogel_pcss_query.comp — vogel_pcss.glsl over a batch of disks.
// Query k: texel k of query image A = (centre x, y, diameter, receiver depth),
//          texel k of query image B = (bias, sample count, turn, 0),
//          texel k of query image C = (receiver plane's gradient, 1: the estimate's turn, 0).
// Result k: (occluders, depth sum, samples, pnInterleavedGradientNoise(centre)) — with C.z = 1 the
// last is the one call's turn, pnVogelPcssEstimate(…, pixel ivec2(centre), …).turn.
//   bindings: vogel_pcss_query.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "vogel_pcss_query.h"
#include "vogel_pcss.glsl"

layout(binding = PN_VOGEL_QUERY_MAP_BINDING) uniform sampler2D pnDepthMap;
layout(binding = PN_VOGEL_QUERY_A_BINDING) uniform sampler2D pnQueryA;
layout(binding = PN_VOGEL_QUERY_B_BINDING) uniform sampler2D pnQueryB;
layout(binding = PN_VOGEL_QUERY_C_BINDING) uniform sampler2D pnQueryC;
layout(rgba32f, binding = PN_VOGEL_QUERY_RESULT_IMAGE) writeonly uniform image2D pnResult;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResult)))) return;
  vec4 a = texelFetch(pnQueryA, p, 0);
  vec4 b = texelFetch(pnQueryB, p, 0);
  vec4 c = texelFetch(pnQueryC, p, 0);
  PnPoisson s = pnVogelOcclusion(pnDepthMap, a.xy, a.z, a.w, b.x, int(b.y), b.z, c.xy);
  float noise = pnInterleavedGradientNoise(a.xy);
  if (c.z == 1.0) {  // any light: the turn is the pixel's alone
    PnLight light = PnLight(1.0, 1.0, 1.0, float(textureSize(pnDepthMap, 0).x), 0.0, 0.0);
    noise = pnVogelPcssEstimate(pnDepthMap, light, vec3(a.xy, a.w), c.xy, ivec2(a.xy), pnVogelPcssDefaults(b.x)).turn;
  }
  imageStore(pnResult, p, vec4(s.occluders, s.depthSum, s.samples, noise));
}
