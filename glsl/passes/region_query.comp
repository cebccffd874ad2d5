// region_query.comp — region.glsl over a batch of regions.
// Query k is texel k of the query image: (x, y, side, unused); result k is
// (origin.x, origin.y, side, level) as floats (exact below 2^24).
//   binding 0: queries (sampler2D, RGBA32F)   binding 2: results (image2D, rgba32f)
//   binding 3: PnRegionQueryParams (std140)

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D pnQueries;
layout(rgba32f, binding = 2) writeonly uniform image2D pnResults;
layout(std140, binding = 3) uniform PnRegionQueryParams {
  int mapSize;
  int centred;  // 0: literal Steps 1–7, 1: centred variant
} pnParams;

#include "region.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResults)))) return;
  vec4 q = texelFetch(pnQueries, p, 0);
  PnWindow w = (pnParams.centred != 0) ? pnRegionApproximateCentred(q.xy, q.z, pnParams.mapSize)
                                       : pnRegionApproximate(q.xy, q.z, pnParams.mapSize);
  imageStore(pnResults, p, vec4(vec2(w.origin), float(w.side), float(w.level)));
}
