// region_query.comp — region.glsl over a batch of regions.
// Query k is texel k of the query image: (x, y, side, unused); result k is
// (origin.x, origin.y, side, level) as floats (exact below 2^24). With pnParams.areas, query k is
// (x, y, side, t) and result k: texel (t, t)'s spans of pnRegionArea(x, y, side) along x and y,
// its overlap with the texels [t, t + (3, 2)), and the overlap of pnRegionAreaOfRect of the
// texels [t, t + (5, 3)) with the texels [floor(x, y), floor(x, y) + 4).
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
  if (pnParams.areas != 0) {
    PnArea a = pnRegionArea(q.xy, q.z, pnParams.mapSize);
    ivec2 t = ivec2(int(q.w));
    ivec2 f = ivec2(floor(q.xy));
    imageStore(pnResults, p, vec4(pnRegionAreaSpan(a, t.x, 0), pnRegionAreaSpan(a, t.y, 1),
                                  pnRegionAreaOver(a, t, t + ivec2(3, 2)),
                                  pnRegionAreaOver(pnRegionAreaOfRect(PnRect(t, ivec2(5, 3))), f, f + ivec2(4))));
    return;
  }
  PnWindow w = (pnParams.centred != 0) ? pnRegionApproximateCentred(q.xy, q.z, pnParams.mapSize)
                                       : pnRegionApproximate(q.xy, q.z, pnParams.mapSize);
  imageStore(pnResults, p, vec4(vec2(w.origin), float(w.side), float(w.level)));
}
