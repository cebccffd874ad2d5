// reuse_gather.comp — every pixel takes its representative's value (reuse.glsl).
// Writes (representative x, representative y, value at the representative, 0).
// Bindings and the parameter block: reuse_gather.h.

layout(local_size_x = 8, local_size_y = 8) in;

#include "reuse_gather.h"

layout(binding = PN_REUSE_GATHER_PARENTS_BINDING) uniform sampler2D pnParents;
layout(binding = PN_REUSE_GATHER_VALUES_BINDING) uniform sampler2D pnValues;
layout(rgba32f, binding = PN_REUSE_GATHER_RESULT_BINDING) writeonly uniform image2D pnResult;

#include "reuse.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResult)))) return;
  ivec2 r = pnReuseRepresentative(pnParents, p, pnParams.tile);
  imageStore(pnResult, p, vec4(vec2(r), texelFetch(pnValues, r, 0).r, 0.0));
}
