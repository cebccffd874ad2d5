// vogel_pcss_query.comp — vogel_pcss.glsl over a batch of disks.
// Query k: texel k of query image A = (centre x, y, diameter, receiver depth),
//          texel k of query image B = (bias, sample count, turn, 0),
//          texel k of query image C = (receiver plane's gradient, 0, 0).
// Result k: (occluders, depth sum, samples, pnInterleavedGradientNoise(centre)).
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
  imageStore(pnResult, p, vec4(s.occluders, s.depthSum, s.samples, pnInterleavedGradientNoise(a.xy)));
}
