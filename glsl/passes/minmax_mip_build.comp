// minmax_mip_build.comp — one level of minmax_mip.glsl's aligned min / max
// mip chain per dispatch (two nodes a texel): the first (node level PN_MIP_FIRST_LEVEL) from the
// shadow map's 4×4 texels (padded to the next power of two), level i from level i-1; pnParams.level
// is the node level, the image bound is its mip level (level - PN_MIP_FIRST_LEVEL). The chain is read (all levels) and
// written (the level being built) through the same texture. A dispatch covers
// the whole level, or only the listed texels (texel_list.glsl) when a cache
// updates the chain where its map changed. Bindings and the parameter block:
// minmax_mip_build.h.

layout(local_size_x = 8, local_size_y = 8) in;

#include "minmax_mip_build.h"

layout(binding = PN_MINMAX_MIP_SHADOW_MAP_BINDING) uniform sampler2D pnShadowMap;
layout(binding = PN_MINMAX_MIP_READ_BINDING) uniform sampler2D pnMipRead;
layout(rgba32f, binding = PN_MINMAX_MIP_WRITE_BINDING) writeonly uniform image2D pnMipWrite;

#include "minmax_mip.glsl"
#define PN_TEXEL_LIST_BINDING PN_MINMAX_MIP_TEXELS_BINDING
#include "texel_list.glsl"

void main() {
  ivec2 p;
  if (!pnTexelListTexel(pnParams.texelFirst, pnParams.texelCount, p) ||
      any(greaterThanEqual(p, imageSize(pnMipWrite)))) return;
  imageStore(pnMipWrite, p, (pnParams.level <= PN_MIP_FIRST_LEVEL) ? pnMipFirstTexel(pnShadowMap, p)
                                                                   : pnMipCombineTexel(pnMipRead, pnParams.level, p));
}
