// summed_area_build.comp — one of the two passes that build a summed_area.glsl
// table. The runner dispatches it twice over an N×M depth map:
//   direction PN_SUMMED_AREA_ROWS: invocation r in [0, M] writes row r of the
//     row-prefix table ((N+1)×(M+1)) from the map;
//   direction PN_SUMMED_AREA_COLUMNS: invocation c in [0, N] writes column c
//     of the table from the row-prefix table, read through a sampler.
// One invocation per line (local size 64), N+1 or M+1 loop iterations each.
// Bindings and the parameter block: summed_area_build.h.
//
// options:
//   PN_SUMMED_AREA_BUILD_KIND   what the table holds (summed_area.h):
//     PN_SUMMED_AREA_KIND_DEPTH (default): depth sums and finite counts, rgba32ui;
//     PN_SUMMED_AREA_KIND_MOMENTS: fixed-point moments of the unit depth, rgba32ui;
//     PN_SUMMED_AREA_KIND_FLOAT_MOMENTS: float moments, rg32f (rgba32f on ES).
//   The runner compiles one program per kind.

layout(local_size_x = 64) in;

#include "summed_area_build.h"

#ifndef PN_SUMMED_AREA_BUILD_KIND
#define PN_SUMMED_AREA_BUILD_KIND PN_SUMMED_AREA_KIND_DEPTH
#endif

layout(binding = PN_SUMMED_AREA_BUILD_MAP_BINDING) uniform sampler2D pnDepthMap;
#if PN_SUMMED_AREA_BUILD_KIND == PN_SUMMED_AREA_KIND_FLOAT_MOMENTS
#define PN_BUILD_SUM vec4
layout(binding = PN_SUMMED_AREA_BUILD_ROWS_BINDING) uniform sampler2D pnRowPrefix;
#if defined(GL_ES)  // ES 3.1 has no rg32f image format
layout(rgba32f, binding = PN_SUMMED_AREA_BUILD_TARGET_IMAGE) writeonly uniform image2D pnTarget;
#else
layout(rg32f, binding = PN_SUMMED_AREA_BUILD_TARGET_IMAGE) writeonly uniform image2D pnTarget;
#endif
#else
#define PN_BUILD_SUM uvec4
layout(binding = PN_SUMMED_AREA_BUILD_ROWS_BINDING) uniform usampler2D pnRowPrefix;
layout(rgba32ui, binding = PN_SUMMED_AREA_BUILD_TARGET_IMAGE) writeonly uniform uimage2D pnTarget;
#endif

#include "summed_area.glsl"

PN_BUILD_SUM rowStep(int row, int x, PN_BUILD_SUM left) {
#if PN_SUMMED_AREA_BUILD_KIND == PN_SUMMED_AREA_KIND_FLOAT_MOMENTS
  return pnSummedAreaFloatMomentsRowStep(pnDepthMap, pnParams.unitRange, row, x, left);
#elif PN_SUMMED_AREA_BUILD_KIND == PN_SUMMED_AREA_KIND_MOMENTS
  return pnSummedAreaMomentsRowStep(pnDepthMap, pnParams.unitRange, row, x, left);
#else
  return pnSummedAreaRowStep(pnDepthMap, row, x, left);
#endif
}

PN_BUILD_SUM columnStep(int column, int y, PN_BUILD_SUM above) {
#if PN_SUMMED_AREA_BUILD_KIND == PN_SUMMED_AREA_KIND_FLOAT_MOMENTS
  return pnSummedAreaFloatMomentsColumnStep(pnRowPrefix, column, y, above);
#elif PN_SUMMED_AREA_BUILD_KIND == PN_SUMMED_AREA_KIND_MOMENTS
  return pnSummedAreaMomentsColumnStep(pnRowPrefix, column, y, above);
#else
  return pnSummedAreaColumnStep(pnRowPrefix, column, y, above);
#endif
}

void main() {
  int line = int(gl_GlobalInvocationID.x);
  PN_BUILD_SUM sum = PN_BUILD_SUM(0);
  if (pnParams.direction == PN_SUMMED_AREA_ROWS) {
    ivec2 t = pnSummedAreaTableSize(textureSize(pnDepthMap, 0));
    if (line >= t.y) return;
    for (int x = 0; x < t.x; ++x) {
      sum = rowStep(line, x, sum);
      imageStore(pnTarget, ivec2(x, line), sum);
    }
  } else {
    ivec2 t = min(textureSize(pnRowPrefix, 0), ivec2(PN_SUMMED_AREA_MAX_SIDE + 1));
    if (line >= t.x) return;
    for (int y = 0; y < t.y; ++y) {
      sum = columnStep(line, y, sum);
      imageStore(pnTarget, ivec2(line, y), sum);
    }
  }
}
