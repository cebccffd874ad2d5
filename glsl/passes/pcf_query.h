// pcf_query.h — what passes/pcf_query.comp and its runner side
// (runner/pass_runners/pcf_pass.cpp) share. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_PCF_QUERY_H
#define PENUMBRA_PASSES_PCF_QUERY_H

#define PN_PCF_QUERY_MAP_BINDING 0      // sampler2D, R32F: the depth map
#define PN_PCF_QUERY_A_BINDING 1        // sampler2D, RGBA32F: (origin x, y, width, height)
#define PN_PCF_QUERY_B_BINDING 2        // sampler2D, RGBA32F: (receiver depth, bias, band rows, 0 window / 1 bilinear)
#define PN_PCF_QUERY_RESULT_IMAGE 3     // image2D, rgba32f: (occluders, depth sum, texels, 0)
#define PN_PCF_QUERY_C_BINDING 4        // sampler2D, RGBA32F: a plane query's (gradient u, v, centre u, v)

#endif  // PENUMBRA_PASSES_PCF_QUERY_H
