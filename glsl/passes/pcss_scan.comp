// pcss_scan.comp — exact PCSS's Steps 4 and 5: every texel of each entry's
// exact region (pcss_regions.glsl) is fetched and compared (pcf.glsl), one
// band of rows per dispatch, added to the previous band's sums (ping-pong:
// GLSL ES has no read-write rgba32f images): llvmpipe ends an invocation's
// loops after 65535 iterations in total, which a whole large window would
// exceed (a band of r rows of a w-wide region costs r · (ceil(w / 16) + 1)).
// Result per pixel: (occluders, depth sum, texels, texels fetched).
// The region and its sums are exact_pcss.glsl's (pn_exactPcssAddRows), so its option
// PN_AREA_EDGES 1 (issue 51) makes them the square with area-weighted edges here too:
// occluders and texels as areas, the texels fetched its cover's.
//   bindings and blocks: pcss_params.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "pcss_params.h"

layout(binding = PN_PCSS_DEPTH_MAP_BINDING) uniform sampler2D pnDepthMap;
layout(binding = PN_PCSS_ENTRIES_BINDING) uniform sampler2D pnEntries;
layout(binding = PN_PCSS_RESULTS_BINDING) uniform sampler2D pnPrevious;
layout(rgba32f, binding = PN_PCSS_RESULT_IMAGE) writeonly uniform image2D pnResult;

#include "exact_pcss.glsl"
#include "pcss_params.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResult)))) return;
  vec4 entry = texelFetch(pnEntries, p, 0);
  vec4 sum = pnPcss.bandStart == 0 ? vec4(0.0) : texelFetch(pnPrevious, p, 0);
  if (!pnEntryLit(entry)) {
    int n = textureSize(pnDepthMap, 0).x;
    // The band's rows added to the running sums, in row order: the bands together equal one scan.
    PnPcf s = pn_exactPcssAddRows(pnDepthMap, entry, n, vec3(entry.yz, entry.x), vec2(0.0), pnPcss.bias,
                                  pnPcss.bandStart, pnPcss.bandRows, PnPcf(sum.x, sum.y, sum.z));
    sum = vec4(s.occluders, s.depthSum, s.texels, sum.w);
    if (pnPcss.bandStart == 0) sum.w = float(pn_exactPcssRegionTexels(entry, n));
  }
  imageStore(pnResult, p, sum);
}
