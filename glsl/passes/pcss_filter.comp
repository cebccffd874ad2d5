// pcss_filter.comp — end of Step 4: each pixel takes the blocker result of
// its representative (reuse.glsl; itself without reuse), and its filter
// region follows from its own entry (pcss_regions.glsl).
//   bindings and blocks: pcss_params.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "pcss_params.h"

layout(binding = PN_PCSS_ENTRIES_BINDING) uniform sampler2D pnSearchMap;
layout(binding = PN_PCSS_PARENTS_BINDING) uniform sampler2D pnParents;
layout(binding = PN_PCSS_RESULTS_BINDING) uniform sampler2D pnBlockers;
layout(rgba32f, binding = PN_PCSS_FILTER_MAP_IMAGE) writeonly uniform image2D pnFilterMap;
layout(r32f, binding = PN_PCSS_BLOCKER_MEAN_IMAGE) writeonly uniform image2D pnBlockerMean;
layout(rgba32f, binding = PN_PCSS_FILTER_KEYS_IMAGE) writeonly uniform image2D pnLinkKeys;

#include "pcss_params.glsl"
#include "pcss_regions.glsl"
#include "reuse.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnFilterMap)))) return;
  vec4 own = texelFetch(pnSearchMap, p, 0);
  bool hasBlocker = false;
  float mean = 0.0;
  if (!pnEntryLit(own)) {  // a lit pixel stays lit whatever its representative found: no chase
    ivec2 r = pnPcss.reuseTile > 0 ? pnReuseRepresentative(pnParents, p, pnPcss.reuseTile) : p;
    vec4 result = texelFetch(pnBlockers, r, 0);
    hasBlocker = result.x > 0.0 && !pnEntryLit(texelFetch(pnSearchMap, r, 0));
    mean = hasBlocker ? result.y / result.x : 0.0;
  }
  vec4 entry = pnFilterEntry(pnPcssLight(), own, mean, hasBlocker, pnPcss.filterScale);
  imageStore(pnFilterMap, p, entry);
  imageStore(pnBlockerMean, p, vec4(pnEntryLit(entry) ? 0.0 : mean));
  if (PN_PCSS_WRITE_KEYS) imageStore(pnLinkKeys, p, pnEntryLinkKey(entry, int(pnPcss.mapSize), PN_PCSS_REGION_MODE));
}
