// depth_pyramid_build.comp — one level of depth_pyramid.glsl.
// Dispatched once per level i = 0 … L over (N - 2^i + 1)² invocations, with a
// texture-fetch barrier between levels: level 0 from the shadow map, level i
// from layer i-1 of the pyramid itself (read through the sampler, written
// through the image; the layers differ, so no texel is read and written in
// the same dispatch). A dispatch covers the whole level, or only the listed
// texels (texel_list.glsl) when a cache updates the pyramid where its map
// changed.
//   bindings and block: depth_pyramid.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "depth_pyramid_bindings.h"

layout(binding = PN_PYRAMID_BUILD_MAP_BINDING) uniform sampler2D pnShadowMap;
layout(binding = PN_PYRAMID_BUILD_READ_BINDING) uniform sampler2DArray pnPyramidRead;
layout(rgba32f, binding = PN_PYRAMID_BUILD_WRITE_IMAGE) writeonly uniform image2DArray pnPyramidWrite;

#include "depth_pyramid.glsl"
#define PN_TEXEL_LIST_BINDING PN_PYRAMID_BUILD_TEXELS_BINDING
#include "texel_list.glsl"

void main() {
  ivec2 p;
  int size = pnPyramidLevelSize(imageSize(pnPyramidWrite).x, pnParams.level);
  if (!pnTexelListTexel(pnParams.texelFirst, pnParams.texelCount, p) || any(greaterThanEqual(p, ivec2(size)))) return;
  vec4 texel = (pnParams.level == 0) ? pnPyramidLevel0(pnShadowMap, p)
                                     : pnPyramidCombine(pnPyramidRead, pnParams.level, p);
  imageStore(pnPyramidWrite, ivec3(p, pnParams.level), texel);
}
