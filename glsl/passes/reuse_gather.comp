// reuse_gather.comp — every pixel takes its representative's value (reuse.glsl).
// Writes (representative x, representative y, value at the representative, 0).
//   binding 0: parents (sampler2D, R32F)   binding 2: result (image2D, rgba32f)
//   binding 1: values  (sampler2D, R32F)   binding 3: PnReuseGatherParams (std140)

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D pnParents;
layout(binding = 1) uniform sampler2D pnValues;
layout(rgba32f, binding = 2) writeonly uniform image2D pnResult;
layout(std140, binding = 3) uniform PnReuseGatherParams {
  int tile;
} pnParams;

#include "reuse.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResult)))) return;
  ivec2 r = pnReuseRepresentative(pnParents, p, pnParams.tile);
  imageStore(pnResult, p, vec4(vec2(r), texelFetch(pnValues, r, 0).r, 0.0));
}
