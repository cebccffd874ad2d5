// pcss_work.glsl — which pixel an invocation of an estimating pass (Steps 4
// and 5: pcss_traverse, pcss_poisson) computes, and how the non-
// representatives of the reuse scheme are skipped:
//   PN_WORK_ALL     one invocation per pixel, all compute;
//   PN_WORK_BRANCH  one per pixel, those with a parent return at once (their
//                   work group still runs: the saving depends on whole groups);
//   PN_WORK_LIST    one per pixel that computes (not lit; a representative when
//                   reuse is on), from the list pcss_compact.comp appended
//                   (dispatched indirectly: no idle invocations).
// The including pass declares layout(local_size_x = 64) in; (the runner
// dispatches 64-wide groups, and the list's header counts groups of 64);
// a pixel index i is (i mod W, i div W).
//   bindings and blocks: pcss_params.h

#ifndef PENUMBRA_PCSS_WORK_GLSL
#define PENUMBRA_PCSS_WORK_GLSL

#include "pcss_params.glsl"
#include "reuse.glsl"

layout(binding = PN_PCSS_PARENTS_BINDING) uniform sampler2D pnParents;
layout(std430, binding = PN_PCSS_WORK_LIST_BINDING) readonly buffer PnWorkList {
  uint groups[3];
  uint count;
  uvec2 pixels[];
} pnWork;

// False when this invocation has no pixel to compute.
bool pnWorkPixel(ivec2 screen, out ivec2 p) {
  uint i = gl_GlobalInvocationID.x;
  if (pnPcss.workMode == PN_WORK_LIST) {
    if (i >= pnWork.count) return false;
    p = ivec2(pnWork.pixels[i]);
    return true;
  }
  if (i >= uint(screen.x * screen.y)) return false;
  p = ivec2(int(i % uint(screen.x)), int(i / uint(screen.x)));
  return pnPcss.workMode == PN_WORK_ALL || int(texelFetch(pnParents, p, 0).r) == PN_REUSE_NONE;
}

#endif  // PENUMBRA_PCSS_WORK_GLSL
