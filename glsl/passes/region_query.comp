// region_query.comp — region.glsl over a batch of regions.
// Query k is texel k of the query image: (x, y, side, unused); result k is
// (origin.x, origin.y, side, level) as floats (exact below 2^24).
// Bindings and the parameter block: region_query.h.

layout(local_size_x = 8, local_size_y = 8) in;

#include "region_query.h"

layout(binding = PN_REGION_QUERY_QUERIES_BINDING) uniform sampler2D pnQueries;
layout(rgba32f, binding = PN_REGION_QUERY_RESULTS_BINDING) writeonly uniform image2D pnResults;

#include "region.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResults)))) return;
  vec4 q = texelFetch(pnQueries, p, 0);
  PnWindow w = (pnParams.centred != 0) ? pnRegionApproximateCentred(q.xy, q.z, pnParams.mapSize)
                                       : pnRegionApproximate(q.xy, q.z, pnParams.mapSize);
  imageStore(pnResults, p, vec4(vec2(w.origin), float(w.side), float(w.level)));
}
