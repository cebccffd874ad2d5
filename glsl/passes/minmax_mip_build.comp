// minmax_mip_build.comp — one level of minmax_mip.glsl's aligned min / max
// mip chain per dispatch (two nodes a texel): level 0 from the shadow map (padded to the next
// power of two), level i from level i-1. The chain is read (all levels) and
// written (the level being built) through the same texture. Bindings and the
// parameter block: minmax_mip_build.h.

layout(local_size_x = 8, local_size_y = 8) in;

#include "minmax_mip_build.h"

layout(binding = PN_MINMAX_MIP_SHADOW_MAP_BINDING) uniform sampler2D pnShadowMap;
layout(binding = PN_MINMAX_MIP_READ_BINDING) uniform sampler2D pnMipRead;
layout(rgba32f, binding = PN_MINMAX_MIP_WRITE_BINDING) writeonly uniform image2D pnMipWrite;

#include "minmax_mip.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnMipWrite)))) return;
  imageStore(pnMipWrite, p, (pnParams.level == 0) ? pnMipLevel0Texel(pnShadowMap, p)
                                                  : pnMipCombineTexel(pnMipRead, pnParams.level, p));
}
