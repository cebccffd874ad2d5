// summed_area_build.comp — one of the two passes that build summed_area.glsl's
// table. The runner dispatches it twice over an N×M depth map:
//   direction PN_SUMMED_AREA_ROWS: invocation r in [0, M] writes row r of the
//     row-prefix table ((N+1)×(M+1), rgba32ui) from the map;
//   direction PN_SUMMED_AREA_COLUMNS: invocation c in [0, N] writes column c
//     of the table from the row-prefix table, read through a usampler.
// One invocation per line (local size 64), N+1 or M+1 loop iterations each.
// Bindings and the parameter block: summed_area_build.h.

layout(local_size_x = 64) in;

#include "summed_area_build.h"

layout(binding = PN_SUMMED_AREA_BUILD_MAP_BINDING) uniform sampler2D pnDepthMap;
layout(binding = PN_SUMMED_AREA_BUILD_ROWS_BINDING) uniform usampler2D pnRowPrefix;
layout(rgba32ui, binding = PN_SUMMED_AREA_BUILD_TARGET_IMAGE) writeonly uniform uimage2D pnTarget;

#include "summed_area.glsl"

void main() {
  int line = int(gl_GlobalInvocationID.x);
  uvec4 sum = uvec4(0u);
  if (pnParams.direction == PN_SUMMED_AREA_ROWS) {
    ivec2 t = pnSummedAreaTableSize(textureSize(pnDepthMap, 0));
    if (line >= t.y) return;
    for (int x = 0; x < t.x; ++x) {
      sum = pnSummedAreaRowStep(pnDepthMap, line, x, sum);
      imageStore(pnTarget, ivec2(x, line), sum);
    }
  } else {
    ivec2 t = min(textureSize(pnRowPrefix, 0), ivec2(PN_SUMMED_AREA_MAX_SIDE + 1));
    if (line >= t.x) return;
    for (int y = 0; y < t.y; ++y) {
      sum = pnSummedAreaColumnStep(pnRowPrefix, line, y, sum);
      imageStore(pnTarget, ivec2(line, y), sum);
    }
  }
}
