// pcss_compact.comp — the list of pixels an estimating pass must compute:
// every representative (no parent, reuse.glsl) whose entry is not lit,
// appended in any order. The header counts work groups of 64 as they fill,
// so it is the dispatch-indirect argument of PN_WORK_LIST (pcss_work.glsl).
//   bindings and blocks: pcss_params.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "pcss_params.h"

layout(binding = PN_PCSS_ENTRIES_BINDING) uniform sampler2D pnEntries;
layout(binding = PN_PCSS_PARENTS_BINDING) uniform sampler2D pnParents;
layout(std430, binding = PN_PCSS_WORK_LIST_BINDING) buffer PnWorkList {
  uint groups[3];
  uint count;
  uvec2 pixels[];
} pnWork;

#include "pcss_params.glsl"
#include "pcss_regions.glsl"
#include "reuse.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, textureSize(pnEntries, 0)))) return;
  if (pnEntryLit(texelFetch(pnEntries, p, 0))) return;
  if (pnPcss.reuseTile > 0 && int(texelFetch(pnParents, p, 0).r) != PN_REUSE_NONE) return;
  uint i = atomicAdd(pnWork.count, 1u);
  pnWork.pixels[i] = uvec2(p);
  if (i % 64u == 0u) atomicAdd(pnWork.groups[0], 1u);
}
