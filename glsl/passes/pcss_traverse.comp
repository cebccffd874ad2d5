// pcss_traverse.comp — Steps 4 and 5 by traversal (traversal.glsl) over each
// entry's region: the exact rectangle or a region.glsl window (pcss_regions.glsl).
// Result per computed pixel: (occluders, depth sum, texels, nodes visited).
//   bindings and blocks: pcss_params.h

layout(local_size_x = 64) in;  // pcss_work.glsl

#include "pcss_params.h"

layout(binding = PN_PCSS_PYRAMID_BINDING) uniform sampler2DArray pnPyramid;
layout(binding = PN_PCSS_MIP_BINDING) uniform sampler2D pnMip;
layout(binding = PN_PCSS_DEPTH_MAP_BINDING) uniform sampler2D pnDepthMap;  // the map the chain is of
layout(binding = PN_PCSS_DEPTH_SUMS_BINDING) uniform usampler2D pnDepthSums;
layout(binding = PN_PCSS_SAMPLE_TABLE_BINDING) uniform sampler2D pnSampleTable;
layout(binding = PN_PCSS_ENTRIES_BINDING) uniform sampler2D pnEntries;
layout(rgba32f, binding = PN_PCSS_RESULT_IMAGE) writeonly uniform image2D pnResult;

#include "pcss_params.glsl"
#include "pcss_regions.glsl"
#include "pcss_work.glsl"
#define PN_TRAVERSAL_SUM_TABLE pnDepthSums  // PN_DEPTH_SUMS_TABLE's exact sums
#include "traversal_mip.glsl"      // and traversal.glsl
#include "traversal_pyramid.glsl"

void main() {
  ivec2 p;
  if (!pnWorkPixel(imageSize(pnResult), p)) return;
  vec4 entry = texelFetch(pnEntries, p, 0);
  if (pnEntryLit(entry)) {
    imageStore(pnResult, p, vec4(0.0));
    return;
  }
  int n = int(pnPcss.mapSize);
  PnArea area = pnEntryArea(entry, n, PN_PCSS_REGION_MODE);  // with PN_AREA_EDGES, the continuous square
  // Fast PCSS's leaf for the region with area-weighted edges (at most a quarter of its side; its texels under 16,
  // fast_pcss.glsl); else, and HQEPCSS's, as the paper's.
  int leafSide = (PN_AREA_EDGES != 0 && PN_PCSS_STRUCTURE == PN_STRUCTURE_MIP)
      ? pnTraversalRegionLeafSide(pnPcss.leafSide, pnPcss.leafDivisor, area.cover.size)
      : pnTraversalLeafSide(pnPcss.leafSide, pnPcss.leafDivisor, area.cover.size);
  PnTraversal r = (PN_PCSS_STRUCTURE == PN_STRUCTURE_MIP && pnPcss.grid > 0)
      ? pn_gridAreaMip(pnDepthMap, pnMip, pnSampleTable, n, area, entry.yzx, vec2(0.0), pnPcss.bias, pnPcss.grid,
                       pnPcss.leafSide, PN_PCSS_LEAF_MODE, PN_PCSS_DEPTH_SUMS, p)
      : (PN_PCSS_STRUCTURE == PN_STRUCTURE_MIP)
      ? pnTraverseAreaMipPlane(pnDepthMap, pnMip, pnSampleTable, n, area, vec3(0.0, 0.0, entry.x), vec2(0.0), pnPcss.bias,
                               leafSide,
                               PN_PCSS_LEAF_MODE, pnPcss.nodeBudget, PN_PCSS_DEPTH_SUMS, p)
      : pnTraverseAreaPlane(pnPyramid, pnSampleTable, area, vec3(0.0, 0.0, entry.x), vec2(0.0), pnPcss.bias, leafSide,
                            PN_PCSS_LEAF_MODE, pnPcss.nodeBudget, p);
  imageStore(pnResult, p, vec4(r.occluders, r.depthSum, r.texels, float(r.nodes)));
}
