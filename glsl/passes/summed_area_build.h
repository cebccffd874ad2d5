// summed_area_build.h — what passes/summed_area_build.comp and its runner side
// (runner/pass_runners/summed_area_pass.cpp) share: binding points and the
// parameter block. Valid as GLSL and as C++.

#ifndef PENUMBRA_PASSES_SUMMED_AREA_BUILD_H
#define PENUMBRA_PASSES_SUMMED_AREA_BUILD_H

#include "uniform_block.h"
#include "summed_area.h"  // glsl/summed_area.h: PN_SUMMED_AREA_ROWS, _COLUMNS, _KIND_*

// Distinct across resource kinds, so the pass is valid Vulkan GLSL as well.
#define PN_SUMMED_AREA_BUILD_MAP_BINDING 0     // sampler2D, R32F: the depth map (rows pass)
#define PN_SUMMED_AREA_BUILD_ROWS_BINDING 1    // usampler2D RGBA32UI (sampler2D RG32F for float moments): the row-prefix table
#define PN_SUMMED_AREA_BUILD_TARGET_IMAGE 2    // uimage2D rgba32ui (image2D rg32f / rgba32f on ES), writeonly: what the pass writes
#define PN_SUMMED_AREA_BUILD_PARAMS_BINDING 3

PN_UNIFORM_BLOCK(PnSummedAreaBuildParams, PN_SUMMED_AREA_BUILD_PARAMS_BINDING)
  int direction;    // PN_SUMMED_AREA_ROWS or PN_SUMMED_AREA_COLUMNS (summed_area.h)
  int pad0;
  vec2 unitRange;   // moments tables: (offset, scale), x = (d - offset) * scale (pnSummedAreaUnitDepth)
PN_END_UNIFORM_BLOCK(pnParams)

#endif  // PENUMBRA_PASSES_SUMMED_AREA_BUILD_H
