// backprojection_query.comp — backprojection.glsl over a batch of receivers.
// Query k: texel k of query image A = (u, v, light depth, bias), of B = (side,
// tolerance, budget, gap), of C = (thickness, slabs, -, -): slabs 1 calls the overload with the second
// layer. Result k: (visibility, blocked samples, nodes visited, patches). Bindings and the light
// block: backprojection_query.h.

layout(local_size_x = 8, local_size_y = 8) in;

#include "backprojection_query.h"
#include "backprojection.glsl"

layout(binding = PN_BACKPROJECTION_QUERY_MIP_BINDING) uniform sampler2D pnMip;
layout(binding = PN_BACKPROJECTION_QUERY_A_BINDING) uniform sampler2D pnQueryA;
layout(binding = PN_BACKPROJECTION_QUERY_B_BINDING) uniform sampler2D pnQueryB;
layout(binding = PN_BACKPROJECTION_QUERY_C_BINDING) uniform sampler2D pnQueryC;
layout(binding = PN_BACKPROJECTION_QUERY_LAYER_BINDING) uniform sampler2D pnSecondMip;
layout(binding = PN_BACKPROJECTION_QUERY_MAP_BINDING) uniform sampler2D pnShadowMap;
layout(binding = PN_BACKPROJECTION_QUERY_LAYER_MAP_BINDING) uniform sampler2D pnSecondMap;
layout(rgba32f, binding = PN_BACKPROJECTION_QUERY_RESULT_IMAGE) writeonly uniform image2D pnResult;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResult)))) return;
  vec4 a = texelFetch(pnQueryA, p, 0);
  vec4 b = texelFetch(pnQueryB, p, 0);
  vec4 c = texelFetch(pnQueryC, p, 0);
  PnBackprojectionSettings s = PnBackprojectionSettings(a.w, int(b.x), b.y, int(b.z), b.w, c.x);
  PnBackprojection r = c.y != 0.0 ? pnBackprojectionWork(pnShadowMap, pnMip, pnSecondMap, pnSecondMip,
                                                         PN_LIGHT_FROM_FIELDS(pnParams), a.xyz, s)
                                  : pnBackprojectionWork(pnShadowMap, pnMip, PN_LIGHT_FROM_FIELDS(pnParams), a.xyz, s);
  imageStore(pnResult, p, vec4(r.visibility, r.blocked, r.nodes, r.patches));
}
