// pcss_regions_query.comp — pcss_regions.glsl over a batch of queries.
// Query k is texel k of query images A, B, C; its kind (B.x) picks the entry:
//   search: pnSearchEntry over the pyramid (receiver A, bias C.x, iterations B.z, mode B.y)
//   search over the mip chain: pnSearchEntryMip, the same inputs
//   counted search over the mip chain: pnSearchEntryMipCounted, the same inputs
//   plane search over the mip chain: pnSearchEntryMipPlane, the same and the gradient C.yz
//   plane search over the pyramid: pnSearchEntryPlane, as search and the gradient C.yz
//   filter: pnFilterEntry (search entry A, blocker mean C.y, has blocker B.w, scale C.z)
//   entry:  A as given
// and result k is that entry, pnEntryRect of it, pnEntryWindow of it in mode B.y
// with pnEntryLit (plus 2 × the counted and plane searches' refinements: the four
// images are GLSL ES 3.10's minimum), and pnEntryLinkKey in mode B.y. Integers
// travel as floats (exact below 2^24). Bindings, kinds and the parameter block: pcss_regions_query.h.

layout(local_size_x = 8, local_size_y = 8) in;

#include "pcss_regions_query.h"

layout(binding = PN_PCSS_REGIONS_QUERY_PYRAMID_BINDING) uniform sampler2DArray pnPyramid;
layout(binding = PN_PCSS_REGIONS_QUERY_MIP_BINDING) uniform sampler2D pnMip;
layout(binding = PN_PCSS_REGIONS_QUERY_A_BINDING) uniform sampler2D pnQueryA;
layout(binding = PN_PCSS_REGIONS_QUERY_B_BINDING) uniform sampler2D pnQueryB;
layout(binding = PN_PCSS_REGIONS_QUERY_C_BINDING) uniform sampler2D pnQueryC;
layout(rgba32f, binding = PN_PCSS_REGIONS_QUERY_ENTRY_BINDING) writeonly uniform image2D pnEntries;
layout(rgba32f, binding = PN_PCSS_REGIONS_QUERY_RECT_BINDING) writeonly uniform image2D pnRects;
layout(rgba32f, binding = PN_PCSS_REGIONS_QUERY_WINDOW_BINDING) writeonly uniform image2D pnWindows;
layout(rgba32f, binding = PN_PCSS_REGIONS_QUERY_KEY_BINDING) writeonly uniform image2D pnKeys;

#include "pcss_regions_mip.glsl"      // and pcss_regions.glsl
#include "pcss_regions_pyramid.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnEntries)))) return;
  vec4 a = texelFetch(pnQueryA, p, 0);
  vec4 b = texelFetch(pnQueryB, p, 0);
  vec4 c = texelFetch(pnQueryC, p, 0);
  int kind = int(b.x), mode = int(b.y);
  int n = int(pnParams.mapSize);
  PnLight light = PN_LIGHT_FROM_FIELDS(pnParams);
  vec4 entry = a;
  int refinements = 0;
  if (kind == PN_PCSS_REGIONS_QUERY_SEARCH_MIP_COUNTED)
    entry = pnSearchEntryMipCounted(pnMip, n, light, a, c.x, int(b.z), refinements);
  else if (kind == PN_PCSS_REGIONS_QUERY_SEARCH_MIP_PLANE)
    entry = pnSearchEntryMipPlane(pnMip, n, light, a, c.yz, c.x, int(b.z), refinements);
  else if (kind == PN_PCSS_REGIONS_QUERY_SEARCH_PLANE)
    entry = pnSearchEntryPlane(pnPyramid, light, a, c.yz, c.x, int(b.z));
  else if (kind == PN_PCSS_REGIONS_QUERY_SEARCH) entry = pnSearchEntry(pnPyramid, light, a, c.x, int(b.z));
  else if (kind == PN_PCSS_REGIONS_QUERY_SEARCH_MIP) entry = pnSearchEntryMip(pnMip, n, light, a, c.x, int(b.z));
  else if (kind == PN_PCSS_REGIONS_QUERY_FILTER) entry = pnFilterEntry(light, a, c.y, b.w != 0.0, c.z);
  PnRect r = pnEntryRect(entry, n);
  PnWindow w = pnEntryWindow(entry, n, mode);
  imageStore(pnEntries, p, entry);
  imageStore(pnRects, p, vec4(vec2(r.origin), vec2(r.size)));
  imageStore(pnWindows, p, vec4(vec2(w.origin), float(w.side), (pnEntryLit(entry) ? 1.0 : 0.0) + 2.0 * float(refinements)));
  imageStore(pnKeys, p, pnEntryLinkKey(entry, n, mode));
}
