// pcss_search.comp — Step 3: the search-region map (pcss_regions.glsl).
//   binding 0: pyramid (sampler2DArray)   binding 2: search map (image2D, rgba32f) out
//   binding 1: G-buffer (sampler2D)       binding 3: link keys (image2D, rgba32f) out
//   binding 7: PnPcssParams

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2DArray pnPyramid;
layout(binding = 1) uniform sampler2D pnGBuffer;
layout(rgba32f, binding = 2) writeonly uniform image2D pnSearchMap;
layout(rgba32f, binding = 3) writeonly uniform image2D pnLinkKeys;

#include "pcss_params.glsl"
#include "pcss_regions.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnSearchMap)))) return;
  vec4 entry = pnSearchEntry(pnPyramid, pnPcssLight(), texelFetch(pnGBuffer, p, 0), pnPcss.bias,
                             pnPcss.refineIterations, pnPcss.regionMode);
  imageStore(pnSearchMap, p, entry);
  imageStore(pnLinkKeys, p, pnEntryLinkKey(entry, pnPyramidMapSize(pnPyramid), pnPcss.regionMode));
}
