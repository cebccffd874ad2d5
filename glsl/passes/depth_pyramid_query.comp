// depth_pyramid_query.comp — any-square min/max queries against a built pyramid.
// Query k is texel k of the query image: (u, v, side, unused) as floats;
// result k is (min, max, 0, 0).
//   binding 0: pyramid (sampler2DArray)      binding 2: results (image2D, rgba32f)
//   binding 1: queries (sampler2D, RGBA32F)

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2DArray pnPyramid;
layout(binding = 1) uniform sampler2D pnQueries;
layout(rgba32f, binding = 2) writeonly uniform image2D pnResults;

#include "depth_pyramid.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResults)))) return;
  vec4 q = texelFetch(pnQueries, p, 0);
  vec2 minMax = pnPyramidSquareMinMax(pnPyramid, ivec2(q.xy), int(q.z));
  imageStore(pnResults, p, vec4(minMax, 0.0, 0.0));
}
