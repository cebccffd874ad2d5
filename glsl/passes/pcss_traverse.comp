// pcss_traverse.comp — Steps 4 and 5 by traversal (traversal.glsl) over each
// entry's region: the exact rectangle or a region.glsl window (pcss_regions.glsl).
// Result per computed pixel: (occluders, depth sum, texels, nodes visited).
//   bindings and blocks: pcss_params.h

layout(local_size_x = 64) in;  // pcss_work.glsl

#include "pcss_params.h"

layout(binding = PN_PCSS_PYRAMID_BINDING) uniform sampler2DArray pnPyramid;
layout(binding = PN_PCSS_SAMPLE_TABLE_BINDING) uniform sampler2D pnSampleTable;
layout(binding = PN_PCSS_ENTRIES_BINDING) uniform sampler2D pnEntries;
layout(rgba32f, binding = PN_PCSS_RESULT_IMAGE) writeonly uniform image2D pnResult;

#include "pcss_params.glsl"
#include "pcss_regions.glsl"
#include "pcss_work.glsl"
#include "traversal.glsl"

void main() {
  ivec2 p;
  if (!pnWorkPixel(imageSize(pnResult), p)) return;
  vec4 entry = texelFetch(pnEntries, p, 0);
  if (pnEntryLit(entry)) {
    imageStore(pnResult, p, vec4(0.0));
    return;
  }
  int n = pnPyramidMapSize(pnPyramid);
  PnTraversal r;
  if (pnPcss.regionMode == PN_REGION_EXACT) {
    PnRect rect = pnEntryRect(entry, n);
    r = pnTraverseRegion(pnPyramid, pnSampleTable, rect.origin, rect.size, entry.x, pnPcss.bias, pnPcss.leafSide,
                         pnPcss.leafMode, pnPcss.nodeBudget, p);
  } else {
    r = pnTraverseWindow(pnPyramid, pnSampleTable, pnEntryWindow(entry, n, pnPcss.regionMode), entry.x, pnPcss.bias, pnPcss.leafSide,
                         pnPcss.leafMode, pnPcss.nodeBudget, p);
  }
  imageStore(pnResult, p, vec4(r.occluders, r.depthSum, r.texels, float(r.nodes)));
}
