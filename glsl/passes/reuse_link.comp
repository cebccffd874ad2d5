// reuse_link.comp — the parent code of every pixel (reuse.glsl), as a float in an r32f image.
// Bindings and the parameter block: reuse_link.h.

layout(local_size_x = 8, local_size_y = 8) in;

#include "reuse_link.h"

layout(binding = PN_REUSE_LINK_ENTRIES_BINDING) uniform sampler2D pnEntries;
layout(r32f, binding = PN_REUSE_LINK_PARENTS_BINDING) writeonly uniform image2D pnParents;

#include "reuse.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnParents)))) return;
  int parent = pnReuseParent(pnEntries, p, pnParams.tile, pnParams.sigma1, pnParams.sigma2, pnParams.sigma3);
  imageStore(pnParents, p, vec4(float(parent), 0.0, 0.0, 0.0));
}
