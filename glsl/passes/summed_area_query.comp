// summed_area_query.comp — summed_area.glsl's rectangle sum over a batch of
// rectangles. Query k: texel k of the rectangle image = (origin x, y, width,
// height), texels. Result k: texel k of the fixed image = (fixed-point sum's
// low word, high word, finite texels, texels covered) and of the float image
// = (depth sum, mean, finite texels, texels covered).
//   bindings: summed_area_query.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "summed_area_query.h"

layout(binding = PN_SUMMED_AREA_QUERY_TABLE_BINDING) uniform usampler2D pnTable;
layout(binding = PN_SUMMED_AREA_QUERY_RECTS_BINDING) uniform sampler2D pnRects;
layout(rgba32ui, binding = PN_SUMMED_AREA_QUERY_FIXED_IMAGE) writeonly uniform uimage2D pnFixedResult;
layout(rgba32f, binding = PN_SUMMED_AREA_QUERY_FLOAT_IMAGE) writeonly uniform image2D pnFloatResult;

#include "summed_area.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnFloatResult)))) return;
  vec4 rect = texelFetch(pnRects, p, 0);
  PnSummedArea s = pnSummedAreaRectSum(pnTable, ivec2(rect.xy), ivec2(rect.zw));
  imageStore(pnFixedResult, p, uvec4(s.fixedSum, uint(s.count), uint(s.texels)));
  imageStore(pnFloatResult, p, vec4(s.sum, pnSummedAreaMean(s), s.count, s.texels));
}
