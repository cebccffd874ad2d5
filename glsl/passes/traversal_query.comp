// traversal_query.comp — traversal.glsl over a batch of receivers, over the
// decreased pyramid or the aligned mip chain (pnParams.structure).
// Query k: texel k of query image A = (region origin x, y, region width, height), or with
//          pnParams.areaRegions (centre x, y, side, 0): pnRegionArea's square, pnTraverseAreaMipPlane
//          (pnTraverseAreaPlane on the pyramid),
//          texel k of query image B = (receiver depth, screen pixel x, y, 0),
//          texel k of query image E = (receiver u, v, receiver-plane gradient u, v): the
//          traversal with that plane (pn_traverseRegionPlane, pnTraverseRegionMipPlane,
//          pnGridRegionMip; gradient 0: none — the mip chain's rectangles then go through
//          pnTraverseRegionMip, and on the pyramid a square through pnTraverseWindow, the same
//          traversals).
// Result k: image C = (occluders, depth sum, texels, 0), image D = (nodes, fetches,
//          pnTraversalBlockerMean, pnTraversalOccludedFraction).
// Bindings and the parameter block: traversal_query.h.

layout(local_size_x = 8, local_size_y = 8) in;

#include "traversal_query.h"

layout(binding = PN_TRAVERSAL_QUERY_PYRAMID_BINDING) uniform sampler2DArray pnPyramid;
layout(binding = PN_TRAVERSAL_QUERY_SAMPLE_TABLE_BINDING) uniform sampler2D pnSampleTable;
layout(binding = PN_TRAVERSAL_QUERY_MIP_BINDING) uniform sampler2D pnMip;
layout(binding = PN_TRAVERSAL_QUERY_MAP_BINDING) uniform sampler2D pnShadowMap;
layout(binding = PN_TRAVERSAL_QUERY_DEPTH_SUMS_BINDING) uniform usampler2D pnDepthSums;
layout(binding = PN_TRAVERSAL_QUERY_A_BINDING) uniform sampler2D pnQueryA;
layout(binding = PN_TRAVERSAL_QUERY_B_BINDING) uniform sampler2D pnQueryB;
layout(binding = PN_TRAVERSAL_QUERY_PLANE_BINDING) uniform sampler2D pnQueryE;
layout(rgba32f, binding = PN_TRAVERSAL_QUERY_RESULT_C_BINDING) writeonly uniform image2D pnResultC;
layout(rgba32f, binding = PN_TRAVERSAL_QUERY_RESULT_D_BINDING) writeonly uniform image2D pnResultD;

#define PN_TRAVERSAL_SUM_TABLE pnDepthSums  // PN_DEPTH_SUMS_TABLE's exact sums
#include "traversal_mip.glsl"      // and traversal.glsl
#include "traversal_pyramid.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResultC)))) return;
  vec4 a = texelFetch(pnQueryA, p, 0);
  vec4 b = texelFetch(pnQueryB, p, 0);
  vec4 e = texelFetch(pnQueryE, p, 0);
  PnArea area = pnParams.areaRegions != 0 ? pnRegionArea(a.xy, a.z, pnParams.mapSize)
                                           : pnRegionAreaOfRect(PnRect(ivec2(a.xy), ivec2(a.zw)));
  // The leaf side as Fast PCSS (regionLeaf) and HQEPCSS take it (divisor 0: the block's side itself).
  int leafSide = pnParams.regionLeaf != 0
      ? pnTraversalRegionLeafSide(pnParams.leafSide, pnParams.leafDivisor, area.cover.size)
      : pnTraversalLeafSide(pnParams.leafSide, pnParams.leafDivisor, area.cover.size);
  PnTraversal r = (pnParams.structure == PN_STRUCTURE_MIP && pnParams.areaRegions != 0)
      ? pnTraverseAreaMipPlane(pnShadowMap, pnMip, pnSampleTable, pnParams.mapSize, area, vec3(e.xy, b.x), e.zw,
                               pnParams.bias, leafSide, pnParams.leafMode, pnParams.nodeBudget, pnParams.depthSums,
                               ivec2(b.yz))
      : (pnParams.areaRegions != 0)
      ? pnTraverseAreaPlane(pnPyramid, pnSampleTable, area, vec3(e.xy, b.x), e.zw, pnParams.bias, leafSide,
                            pnParams.leafMode, pnParams.nodeBudget, ivec2(b.yz))
      : (pnParams.structure == PN_STRUCTURE_MIP && pnParams.grid > 0)
      ? pnGridRegionMip(pnShadowMap, pnMip, pnSampleTable, pnParams.mapSize, ivec2(a.xy), ivec2(a.zw), vec3(e.xy, b.x), e.zw,
                        pnParams.bias, pnParams.grid, leafSide, pnParams.leafMode, pnParams.depthSums,
                        ivec2(b.yz))
      : (pnParams.structure == PN_STRUCTURE_MIP && all(equal(e.zw, vec2(0.0))))  // no plane: the plain call
      ? pnTraverseRegionMip(pnShadowMap, pnMip, pnSampleTable, pnParams.mapSize, ivec2(a.xy), ivec2(a.zw), b.x,
                            pnParams.bias, leafSide, pnParams.leafMode, pnParams.nodeBudget, pnParams.depthSums,
                            ivec2(b.yz))
      : (pnParams.structure == PN_STRUCTURE_MIP)
      ? pnTraverseRegionMipPlane(pnShadowMap, pnMip, pnSampleTable, pnParams.mapSize, ivec2(a.xy), ivec2(a.zw),
                                 vec3(e.xy, b.x), e.zw, pnParams.bias, leafSide, pnParams.leafMode,
                                 pnParams.nodeBudget, pnParams.depthSums, ivec2(b.yz))
      : (all(equal(e.zw, vec2(0.0))) && a.z == a.w)  // a square without a plane: region.glsl's window form
      ? pnTraverseWindow(pnPyramid, pnSampleTable, PnWindow(ivec2(a.xy), int(a.z), 0), b.x, pnParams.bias,
                         leafSide, pnParams.leafMode, pnParams.nodeBudget, ivec2(b.yz))
      : pn_traverseRegionPlane(pnPyramid, pnSampleTable, ivec2(a.xy), ivec2(a.zw), vec3(e.xy, b.x), e.zw,
                               pnParams.bias, leafSide, pnParams.leafMode, pnParams.nodeBudget, ivec2(b.yz));
  imageStore(pnResultC, p, vec4(r.occluders, r.depthSum, r.texels, 0.0));
  imageStore(pnResultD, p, vec4(float(r.nodes), float(r.fetches), pnTraversalBlockerMean(r), pnTraversalOccludedFraction(r)));
}
