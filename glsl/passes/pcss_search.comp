// pcss_search.comp — Step 3: the search-region map (pcss_regions.glsl).
//   bindings and blocks: pcss_params.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "pcss_params.h"

layout(binding = PN_PCSS_PYRAMID_BINDING) uniform sampler2DArray pnPyramid;
layout(binding = PN_PCSS_GBUFFER_BINDING) uniform sampler2D pnGBuffer;
layout(rgba32f, binding = PN_PCSS_SEARCH_MAP_IMAGE) writeonly uniform image2D pnSearchMap;
layout(rgba32f, binding = PN_PCSS_SEARCH_KEYS_IMAGE) writeonly uniform image2D pnLinkKeys;

#include "pcss_params.glsl"
#include "pcss_regions.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnSearchMap)))) return;
  vec4 entry = pnSearchEntry(pnPyramid, pnPcssLight(), texelFetch(pnGBuffer, p, 0), pnPcss.bias,
                             pnPcss.refineIterations);
  imageStore(pnSearchMap, p, entry);
  imageStore(pnLinkKeys, p, pnEntryLinkKey(entry, pnPyramidMapSize(pnPyramid), pnPcss.regionMode));
}
