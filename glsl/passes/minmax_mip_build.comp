// minmax_mip_build.comp — baseline for `penumbra bench pyramid`: the plain,
// aligned min / max / mean mip chain that HQEPCSS-style methods build.
// Level i has ceil(N / 2^i)² texels; texel (x, y) combines texels 2x, 2x+1 ×
// 2y, 2y+1 of level i-1 (clamped at odd edges). One dispatch per level.
// The chain is read (all levels) and written (the level being built) through
// the same texture. Bindings and the parameter block: minmax_mip_build.h.

layout(local_size_x = 8, local_size_y = 8) in;

#include "minmax_mip_build.h"

layout(binding = PN_MINMAX_MIP_SHADOW_MAP_BINDING) uniform sampler2D pnShadowMap;
layout(binding = PN_MINMAX_MIP_READ_BINDING) uniform sampler2D pnMipRead;
layout(rgba32f, binding = PN_MINMAX_MIP_WRITE_BINDING) writeonly uniform image2D pnMipWrite;

#include "depth_pyramid.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnMipWrite)))) return;
  if (pnParams.level == 0) {
    imageStore(pnMipWrite, p, pnPyramidLevel0(pnShadowMap, p));
    return;
  }
  int below = pnParams.level - 1;
  ivec2 last = textureSize(pnMipRead, below) - ivec2(1);
  vec4 a = texelFetch(pnMipRead, min(2 * p, last), below);
  vec4 b = texelFetch(pnMipRead, min(2 * p + ivec2(1, 0), last), below);
  vec4 c = texelFetch(pnMipRead, min(2 * p + ivec2(0, 1), last), below);
  vec4 d = texelFetch(pnMipRead, min(2 * p + ivec2(1, 1), last), below);
  imageStore(pnMipWrite, p, vec4(min(min(a.x, b.x), min(c.x, d.x)), max(max(a.y, b.y), max(c.y, d.y)),
                                 ((a.z + b.z) + (c.z + d.z)) * 0.25, 0.0));
}
