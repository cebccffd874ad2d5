// vogel_pcss_query.h — what passes/vogel_pcss_query.comp and its runner side
// (runner/pass_runners/vogel_pcss_pass.cpp) share. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_VOGEL_PCSS_QUERY_H
#define PENUMBRA_PASSES_VOGEL_PCSS_QUERY_H

#define PN_VOGEL_QUERY_MAP_BINDING 0   // sampler2D, R32F: the depth map
#define PN_VOGEL_QUERY_A_BINDING 1     // sampler2D, RGBA32F: (centre x, y, diameter, receiver depth)
#define PN_VOGEL_QUERY_B_BINDING 2     // sampler2D, RGBA32F: (bias, sample count, turn, 0)
#define PN_VOGEL_QUERY_C_BINDING 4     // sampler2D, RGBA32F: (receiver plane's gradient, estimate's turn?, 0)
#define PN_VOGEL_QUERY_RESULT_IMAGE 3  // image2D, rgba32f: (occluders, depth sum, samples, noise at the centre)

#endif  // PENUMBRA_PASSES_VOGEL_PCSS_QUERY_H
