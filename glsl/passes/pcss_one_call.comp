// pcss_one_call.comp — the one-call PCSS techniques (pcss_one_call.glsl) in a
// compute pass, one invocation a pixel: the runner's default path for `fast`
// and `poisson`. Writes the visibility, and with PN_PCSS_WRITE_WORK the
// whole result (visibility, work, work, flags) and the fetches for the frame's statistics.
//   bindings and blocks: pcss_params.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "pcss_one_call.glsl"

#ifndef PN_PCSS_WRITE_WORK
#define PN_PCSS_WRITE_WORK true
#endif

layout(r32f, binding = PN_PCSS_VISIBILITY_IMAGE) writeonly uniform image2D pnVisibility;
layout(rgba32f, binding = PN_PCSS_WORK_IMAGE) writeonly uniform image2D pnWork;
layout(r32f, binding = PN_PCSS_FETCH_IMAGE) writeonly uniform image2D pnFetches;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnVisibility)))) return;
  float fetches;
  vec4 shaded = pnOneCallShade(p, fetches);
  imageStore(pnVisibility, p, vec4(shaded.x));
  if (PN_PCSS_WRITE_WORK) {
    imageStore(pnWork, p, shaded);
    imageStore(pnFetches, p, vec4(fetches));
  }
}
