// correlated_multi_jitter_query.comp — correlated_multi_jitter.glsl over a batch of queries.
// Query k: (group k, sample index, set, seed) as floats; result k: (x, y, 0, 0).
// Bindings: correlated_multi_jitter_query.h.

layout(local_size_x = 8, local_size_y = 8) in;

#include "correlated_multi_jitter_query.h"

layout(binding = PN_CMJ_QUERY_QUERIES_BINDING) uniform sampler2D pnQueries;
layout(rgba32f, binding = PN_CMJ_QUERY_RESULTS_BINDING) writeonly uniform image2D pnResults;

#include "correlated_multi_jitter.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResults)))) return;
  vec4 q = texelFetch(pnQueries, p, 0);
  vec2 position = pnSampleStateless(int(q.x), int(q.y), int(q.z), uint(q.w));
  imageStore(pnResults, p, vec4(position, 0.0, 0.0));
}
