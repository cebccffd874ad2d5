// light_model_query.comp — light_model.glsl over a batch of (receiver depth, blocker depth).
// Result k: (blocker window texels, search width texels, penumbra world, penumbra texels).
// Bindings and the light's parameter block: light_model_query.h.

layout(local_size_x = 8, local_size_y = 8) in;

#include "light_model_query.h"

layout(binding = PN_LIGHT_MODEL_QUERY_QUERIES_BINDING) uniform sampler2D pnQueries;
layout(rgba32f, binding = PN_LIGHT_MODEL_QUERY_RESULTS_BINDING) writeonly uniform image2D pnResults;

#include "light_model.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResults)))) return;
  vec4 q = texelFetch(pnQueries, p, 0);
  PnLight light = PN_LIGHT_FROM_FIELDS(pnParams);
  imageStore(pnResults, p, vec4(pnLightBlockerWindowTexels(light, q.x, q.y), pnLightSearchWidthTexels(light, q.x),
                                pnLightPenumbraWorld(light, q.x, q.y), pnLightPenumbraTexels(light, q.x, q.y)));
}
