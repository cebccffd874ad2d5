// depth_cache_query.comp — depth_cache.glsl over a batch of receivers, for
// the check: query k = (u, v, receiver depth, bias) -> (composed depth at
// texel (u, v), visibility, 0, 0).
//   bindings: depth_cache.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "depth_cache.h"

layout(binding = PN_DEPTH_CACHE_STATIC_BINDING) uniform sampler2D pnStaticMap;
layout(binding = PN_DEPTH_CACHE_DYNAMIC_BINDING) uniform sampler2D pnDynamicMap;
layout(binding = PN_DEPTH_CACHE_QUERIES_BINDING) uniform sampler2D pnQueries;
layout(rgba32f, binding = PN_DEPTH_CACHE_RESULTS_IMAGE) writeonly uniform image2D pnResults;

#include "depth_cache.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResults)))) return;
  vec4 q = texelFetch(pnQueries, p, 0);
  ivec2 texel = ivec2(q.xy);
  float composed = pnDepthCacheComposeAt(pnStaticMap, pnDynamicMap, texel);
  float lit = pnDepthCacheVisibility(pnStaticMap, pnDynamicMap, texel, q.z, q.w);
  imageStore(pnResults, p, vec4(composed, lit, 0.0, 0.0));
}
