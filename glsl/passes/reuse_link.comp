// reuse_link.comp — the parent code of every pixel (reuse.glsl), as a float in an r32f image.
//   binding 0: entries (sampler2D, RGBA32F: d, x, y, s)   binding 2: parents (image2D, r32f)
//   binding 3: PnReuseParams (std140)

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D pnEntries;
layout(r32f, binding = 2) writeonly uniform image2D pnParents;
layout(std140, binding = 3) uniform PnReuseParams {
  float sigma1;
  float sigma2;
  float sigma3;
  int tile;
} pnParams;

#include "reuse.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnParents)))) return;
  int parent = pnReuseParent(pnEntries, p, pnParams.tile, pnParams.sigma1, pnParams.sigma2, pnParams.sigma3);
  imageStore(pnParents, p, vec4(float(parent), 0.0, 0.0, 0.0));
}
