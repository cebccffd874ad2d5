// depth_pyramid_build.comp — one level of depth_pyramid.glsl.
// Dispatched once per level i = 0 … L over (N - 2^i + 1)² invocations, with a
// texture-fetch barrier between levels: level 0 from the shadow map, level i
// from layer i-1 of the pyramid itself (read through the sampler, written
// through the image; the layers differ, so no texel is read and written in
// the same dispatch).
//   binding 0: shadow map (sampler2D, R32F, N×N)
//   binding 1: pyramid    (sampler2DArray, RGBA32F), the same texture as binding 2
//   binding 2: pyramid    (image2DArray, rgba32f, layered)
//   binding 3: PnPyramidBuildParams (std140)

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D pnShadowMap;
layout(binding = 1) uniform sampler2DArray pnPyramidRead;
layout(rgba32f, binding = 2) writeonly uniform image2DArray pnPyramidWrite;
layout(std140, binding = 3) uniform PnPyramidBuildParams {
  int level;
} pnParams;

#include "depth_pyramid.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  int size = pnPyramidLevelSize(imageSize(pnPyramidWrite).x, pnParams.level);
  if (any(greaterThanEqual(p, ivec2(size)))) return;
  vec4 texel = (pnParams.level == 0) ? pnPyramidLevel0(pnShadowMap, p)
                                     : pnPyramidCombine(pnPyramidRead, pnParams.level, p);
  imageStore(pnPyramidWrite, ivec3(p, pnParams.level), texel);
}
