// window_scan.h — what passes/window_scan.comp and its runner side
// (runner/pass_runners/traversal_pass.cpp, WindowScanPass) share: binding points
// and the parameter block, laid out like traversal_query.h (the same query
// and result images) without the sample table. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_WINDOW_SCAN_H
#define PENUMBRA_PASSES_WINDOW_SCAN_H

#include "uniform_block.h"

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_WINDOW_SCAN_PYRAMID_BINDING 0   // sampler2DArray, RGBA32F: level 0 is the sanitized map
#define PN_WINDOW_SCAN_A_BINDING 2         // sampler2D, RGBA32F: region origin x, y, width, height
#define PN_WINDOW_SCAN_RESULT_C_BINDING 3  // image2D, rgba32f: occluders, depth sum, texels, 0
#define PN_WINDOW_SCAN_RESULT_D_BINDING 4  // image2D, rgba32f: 0, fetches, 0, 0
#define PN_WINDOW_SCAN_B_BINDING 5         // sampler2D, RGBA32F: receiver depth, -, -, -
#define PN_WINDOW_SCAN_PARAMS_BINDING 6
#define PN_WINDOW_SCAN_PLANE_BINDING 9     // the traversal batch's receiver planes: not read (no plane)

PN_UNIFORM_BLOCK(PnWindowScanParams, PN_WINDOW_SCAN_PARAMS_BINDING)
  float bias;
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_WINDOW_SCAN_H
