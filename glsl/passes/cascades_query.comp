// cascades_query.comp — cascades.glsl and cascades.h over a batch of queries
// of one kind (cascades_query.h says what each query holds and returns).

layout(local_size_x = 8, local_size_y = 8) in;

#include "cascades_query.h"

layout(binding = PN_CASCADES_QUERY_QUERIES_BINDING) uniform sampler2D pnQueries;
layout(rgba32f, binding = PN_CASCADES_QUERY_RESULTS_BINDING) writeonly uniform image2D pnResults;

#include "cascades.glsl"

vec4 splits(vec4 q) {
  int code = int(q.w);
  int i = code % 16, m = code / 16;
  return vec4(pnCascadePracticalSplit(q.x, q.y, q.z, i, m),
              pnCascadeHybridSplit(q.x, q.y, q.z, i, m, pnParams.enlargement, pnParams.gap),
              pnCascadeAdaptiveLambda(q.y, q.z), pnCascadeEnlargement(pnParams.enlargement, i));
}

vec4 select(vec4 q) {
  PnCascadeChoice c = pnCascadeSelect(q.x, pnParams.near, pnParams.splitFar, pnParams.count, pnParams.band,
                                      pnParams.fadeLast != 0);
  // A visibility that differs per cascade, 0.1 + 0.2 c, blended as a technique blends its cascades.
  float visibility = 0.1 + 0.2 * float(c.index), nextVisibility = 0.1 + 0.2 * float(c.next);
  return vec4(float(c.index), float(c.next), c.nextWeight, pnCascadeBlend(visibility, nextVisibility, c));
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResults)))) return;
  vec4 q = texelFetch(pnQueries, p, 0);
  vec4 result = vec4(0.0);
  if (pnParams.kind == PN_CASCADES_QUERY_SPLITS) result = splits(q);
  else if (pnParams.kind == PN_CASCADES_QUERY_SELECT) result = select(q);
  else if (pnParams.kind == PN_CASCADES_QUERY_SPHERE) result = vec4(pnCascadeSliceSphere(q.x, q.y, q.z), 0.0, 0.0);
  else result = vec4(pnCascadeSnapTexels(q.xy, q.z), 0.0, 0.0);
  imageStore(pnResults, p, result);
}
