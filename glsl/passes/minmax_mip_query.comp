// minmax_mip_query.comp — minmax_mip.glsl's reads of a built chain over a batch of queries.
// Query k: texel k of A = (origin x, y, side, map size), of B = (level, texel x, texel y, 0).
// Result k: (pnMipSquareMinMax(chain, A.w, A.xy, A.z), 0, 0), and pnMipCombineTexel(chain, B.x, B.yz)
// — the chain's combine of level B.x's texel from the level below, as its build makes it.
//   bindings: minmax_mip_query.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "minmax_mip_query.h"

layout(binding = PN_MINMAX_MIP_QUERY_MIP_BINDING) uniform sampler2D pnMip;
layout(binding = PN_MINMAX_MIP_QUERY_A_BINDING) uniform sampler2D pnQueryA;
layout(binding = PN_MINMAX_MIP_QUERY_B_BINDING) uniform sampler2D pnQueryB;
layout(rgba32f, binding = PN_MINMAX_MIP_QUERY_SQUARE_IMAGE) writeonly uniform image2D pnSquares;
layout(rgba32f, binding = PN_MINMAX_MIP_QUERY_COMBINE_IMAGE) writeonly uniform image2D pnCombined;

#include "minmax_mip.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnSquares)))) return;
  vec4 a = texelFetch(pnQueryA, p, 0);
  vec4 b = texelFetch(pnQueryB, p, 0);
  imageStore(pnSquares, p, vec4(pnMipSquareMinMax(pnMip, int(a.w), ivec2(a.xy), int(a.z)), 0.0, 0.0));
  imageStore(pnCombined, p, pnMipCombineTexel(pnMip, int(b.x), ivec2(b.yz)));
}
