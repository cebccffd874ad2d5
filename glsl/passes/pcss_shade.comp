// pcss_shade.comp — end of Step 5: each pixel takes the occluded fraction of
// its representative (reuse.glsl; itself without reuse); visibility = 1 -
// fraction, 1 for a lit entry. This is the soft-shadow map before the blur.
//   bindings and blocks: pcss_params.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "pcss_params.h"

layout(binding = PN_PCSS_ENTRIES_BINDING) uniform sampler2D pnFilterMap;
layout(binding = PN_PCSS_PARENTS_BINDING) uniform sampler2D pnParents;
layout(binding = PN_PCSS_RESULTS_BINDING) uniform sampler2D pnOcclusion;
layout(r32f, binding = PN_PCSS_VISIBILITY_IMAGE) writeonly uniform image2D pnVisibility;

#include "pcss_params.glsl"
#include "pcss_regions.glsl"
#include "reuse.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnVisibility)))) return;
  float fraction = 0.0;
  if (!pnEntryLit(texelFetch(pnFilterMap, p, 0))) {  // a lit pixel is lit whatever its representative found
    ivec2 r = pnPcss.reuseTile > 0 ? pnReuseRepresentative(pnParents, p, pnPcss.reuseTile) : p;
    vec4 result = texelFetch(pnOcclusion, r, 0);
    bool lit = pnEntryLit(texelFetch(pnFilterMap, r, 0));
    fraction = (!lit && result.z > 0.0) ? min(result.x / result.z, 1.0) : 0.0;  // as pnTraversalOccludedFraction
  }
  imageStore(pnVisibility, p, vec4(1.0 - fraction));
}
