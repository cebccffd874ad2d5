// depth_pyramid_query.comp — any-square min/max queries against a built pyramid.
// Query k is texel k of the query image: (u, v, side, unused) as floats;
// result k is (min, max, 0, 0).
//   bindings: depth_pyramid.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "depth_pyramid_bindings.h"

layout(binding = PN_PYRAMID_QUERY_PYRAMID_BINDING) uniform sampler2DArray pnPyramid;
layout(binding = PN_PYRAMID_QUERY_QUERIES_BINDING) uniform sampler2D pnQueries;
layout(rgba32f, binding = PN_PYRAMID_QUERY_RESULTS_IMAGE) writeonly uniform image2D pnResults;

#include "depth_pyramid.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResults)))) return;
  vec4 q = texelFetch(pnQueries, p, 0);
  vec2 minMax = pnPyramidSquareMinMax(pnPyramid, ivec2(q.xy), int(q.z));
  imageStore(pnResults, p, vec4(minMax, 0.0, 0.0));
}
