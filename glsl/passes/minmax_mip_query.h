// minmax_mip_query.h — what passes/minmax_mip_query.comp and its runner side
// (runner/pass_runners/minmax_mip_query_pass.cpp) share. Valid as GLSL and as C++.
#ifndef PENUMBRA_PASSES_MINMAX_MIP_QUERY_H
#define PENUMBRA_PASSES_MINMAX_MIP_QUERY_H

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_MINMAX_MIP_QUERY_MIP_BINDING 0      // sampler2D, RGBA32F: the aligned min/max chain (minmax_mip.glsl)
#define PN_MINMAX_MIP_QUERY_A_BINDING 1        // sampler2D, RGBA32F: (origin x, y, side, map size)
#define PN_MINMAX_MIP_QUERY_B_BINDING 2        // sampler2D, RGBA32F: (level, texel x, texel y, 0)
#define PN_MINMAX_MIP_QUERY_SQUARE_IMAGE 3     // image2D, rgba32f: (pnMipSquareMinMax, 0, 0)
#define PN_MINMAX_MIP_QUERY_COMBINE_IMAGE 4    // image2D, rgba32f: pnMipCombineTexel (two nodes)

#endif  // PENUMBRA_PASSES_MINMAX_MIP_QUERY_H
