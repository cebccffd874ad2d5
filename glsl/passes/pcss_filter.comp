// pcss_filter.comp — end of Step 4: each pixel takes the blocker result of
// its representative (reuse.glsl; itself without reuse), and its filter
// region follows from its own entry (pcss_regions.glsl).
//   binding 2: search map (sampler2D)           image 0: filter map (rgba32f) out
//   binding 4: parent codes (sampler2D, R32F)   image 1: blocker mean (r32f) out, 0 if none
//   binding 5: blocker results (sampler2D)      image 2: link keys (rgba32f) out
//   binding 7: PnPcssParams

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 2) uniform sampler2D pnSearchMap;
layout(binding = 4) uniform sampler2D pnParents;
layout(binding = 5) uniform sampler2D pnBlockers;
layout(rgba32f, binding = 0) writeonly uniform image2D pnFilterMap;
layout(r32f, binding = 1) writeonly uniform image2D pnBlockerMean;
layout(rgba32f, binding = 2) writeonly uniform image2D pnLinkKeys;

#include "pcss_params.glsl"
#include "pcss_regions.glsl"
#include "reuse.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnFilterMap)))) return;
  ivec2 r = pnPcss.reuseTile > 0 ? pnReuseRepresentative(pnParents, p, pnPcss.reuseTile) : p;
  vec4 result = texelFetch(pnBlockers, r, 0);
  bool hasBlocker = result.x > 0.0 && !pnEntryLit(texelFetch(pnSearchMap, r, 0));
  float mean = hasBlocker ? result.y / result.x : 0.0;
  vec4 entry = pnFilterEntry(pnPcssLight(), texelFetch(pnSearchMap, p, 0), mean, hasBlocker, pnPcss.filterScale);
  imageStore(pnFilterMap, p, entry);
  imageStore(pnBlockerMean, p, vec4(pnEntryLit(entry) ? 0.0 : mean));
  imageStore(pnLinkKeys, p, pnEntryLinkKey(entry, int(pnPcss.mapSize), pnPcss.regionMode));
}
