// traversal_query.h — what passes/traversal_query.comp and its runner side
// (runner/pass_runners/traversal_pass.cpp, TraversalPass) share: binding points and
// the parameter block. window_scan.h gives its baseline the same layout.
// Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_TRAVERSAL_QUERY_H
#define PENUMBRA_PASSES_TRAVERSAL_QUERY_H

#include "uniform_block.h"

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_TRAVERSAL_QUERY_PYRAMID_BINDING 0       // sampler2DArray, RGBA32F (depth_pyramid.glsl)
#define PN_TRAVERSAL_QUERY_SAMPLE_TABLE_BINDING 1  // sampler2D, RG32F (sample_table.glsl)
#define PN_TRAVERSAL_QUERY_A_BINDING 2             // sampler2D, RGBA32F: region origin x, y, width, height
                                                   // (areaRegions: centre x, y, side, 0)
#define PN_TRAVERSAL_QUERY_RESULT_C_BINDING 3      // image2D, rgba32f: occluders, depth sum, texels, 0
#define PN_TRAVERSAL_QUERY_RESULT_D_BINDING 4      // image2D, rgba32f: nodes, fetches, blocker mean, occluded fraction
#define PN_TRAVERSAL_QUERY_B_BINDING 5             // sampler2D, RGBA32F: receiver depth, pixel x, y, 0
#define PN_TRAVERSAL_QUERY_PARAMS_BINDING 6
#define PN_TRAVERSAL_QUERY_MIP_BINDING 7           // sampler2D, RGBA32F (minmax_mip.glsl)
#define PN_TRAVERSAL_QUERY_DEPTH_SUMS_BINDING 8    // usampler2D, RGBA32UI (summed_area.glsl)
#define PN_TRAVERSAL_QUERY_PLANE_BINDING 9         // sampler2D, RGBA32F: receiver u, v, its plane's gradient u, v
#define PN_TRAVERSAL_QUERY_MAP_BINDING 10          // sampler2D: the map the mip chain is of

PN_UNIFORM_BLOCK(PnTraversalQueryParams, PN_TRAVERSAL_QUERY_PARAMS_BINDING)
  float bias;
  int leafSide;
  int leafMode;  // PN_LEAF_SAMPLED, PN_LEAF_MIN or PN_LEAF_RAMP (traversal.h)
  int nodeBudget;
  int structure;     // PN_STRUCTURE_* (traversal.h)
  int depthSums;     // the mip chain's traversal: PN_DEPTH_SUMS_* (traversal.h)
  int mapSize;       // the map side N of the mip chain (or of the pyramid)
  int grid;          // the mip chain: > 0: pnGridRegionMip with this many cells a side
  int leafDivisor;   // pnTraversalLeafSide's: the leaf side at least the region's longer side / this (0: off)
  int areaRegions;   // 1: query A is (centre x, y, side, 0), the area-weighted square (either structure)
                     // pnRegionArea (issue 51), traversed by pnTraverseAreaMipPlane
  int regionLeaf;    // 1: the leaf side is pnTraversalRegionLeafSide's (Fast PCSS's over area-weighted squares)
  int pad0;          // the block a whole number of 16-byte rows
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_TRAVERSAL_QUERY_H
