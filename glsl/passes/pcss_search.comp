// pcss_search.comp — Step 3: the search-region map (pcss_regions.glsl), and
// each receiver's light depth (+Inf where the pixel sees no surface): the
// depth Step 6's depth-aware blur cuts at, so it never blurs across a depth
// edge of the G-buffer nor into or out of pixels that see no surface.
//   bindings and blocks: pcss_params.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "pcss_params.h"

layout(binding = PN_PCSS_PYRAMID_BINDING) uniform sampler2DArray pnPyramid;
layout(binding = PN_PCSS_MIP_BINDING) uniform sampler2D pnMip;
layout(binding = PN_PCSS_GBUFFER_BINDING) uniform sampler2D pnGBuffer;
layout(rgba32f, binding = PN_PCSS_SEARCH_MAP_IMAGE) writeonly uniform image2D pnSearchMap;
layout(rgba32f, binding = PN_PCSS_SEARCH_KEYS_IMAGE) writeonly uniform image2D pnLinkKeys;
layout(r32f, binding = PN_PCSS_RECEIVER_DEPTH_IMAGE) writeonly uniform image2D pnReceiverDepth;

#include "pcss_params.glsl"
#include "pcss_regions_mip.glsl"      // and pcss_regions.glsl
#include "pcss_regions_pyramid.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnSearchMap)))) return;
  vec4 receiver = texelFetch(pnGBuffer, p, 0);
  int n = int(pnPcss.mapSize);
  vec4 entry = (PN_PCSS_STRUCTURE == PN_STRUCTURE_MIP)
      ? pnSearchEntryMip(pnMip, n, pnPcssLight(), receiver, pnPcss.bias, pnPcss.refineIterations)
      : pnSearchEntry(pnPyramid, pnPcssLight(), receiver, pnPcss.bias, pnPcss.refineIterations);
  bool surface = receiver.w != 0.0 && !isnan(receiver.z) && !isinf(receiver.z);
  imageStore(pnReceiverDepth, p, vec4(surface ? receiver.z : pn_pyramidFar(), 0.0, 0.0, 0.0));
  imageStore(pnSearchMap, p, entry);
  if (PN_PCSS_WRITE_KEYS) imageStore(pnLinkKeys, p, pnEntryLinkKey(entry, n, PN_PCSS_REGION_MODE));
}
