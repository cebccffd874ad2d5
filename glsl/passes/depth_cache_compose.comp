// depth_cache_compose.comp — depth_cache.glsl's composition of the static and
// dynamic maps written into the composed map: everywhere (the seed's cache),
// or over the listed texels (texel_list.glsl) of the dirty rectangles (the
// runner's cache); texels outside them keep what they held.
//   bindings and block: depth_cache.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "depth_cache.h"

layout(binding = PN_DEPTH_CACHE_STATIC_BINDING) uniform sampler2D pnStaticMap;
layout(binding = PN_DEPTH_CACHE_DYNAMIC_BINDING) uniform sampler2D pnDynamicMap;
layout(r32f, binding = PN_DEPTH_CACHE_COMPOSED_IMAGE) writeonly uniform image2D pnComposedMap;

#include "depth_cache.glsl"
#define PN_TEXEL_LIST_BINDING PN_DEPTH_CACHE_TEXELS_BINDING
#include "texel_list.glsl"

void main() {
  ivec2 p;
  if (!pnTexelListTexel(pnParams.texelFirst, pnParams.texelCount, p) ||
      any(greaterThanEqual(p, imageSize(pnComposedMap)))) return;
  imageStore(pnComposedMap, p, vec4(pnDepthCacheComposeAt(pnStaticMap, pnDynamicMap, p), 0.0, 0.0, 0.0));
}
