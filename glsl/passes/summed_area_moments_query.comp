// summed_area_moments_query.comp — summed_area.glsl's moments over a batch of
// rectangles of a moments table. Query k: texel k of the rectangle image =
// (origin x, y, width, height), texels. Result k: texel k of the moments image
// = (mean, variance of the unit depth x, texels covered, 0) and, for the
// fixed-point table, of the sums image = (sum of q low, high word, sum of q^2
// low, high word), the exact box sums.
//   bindings: summed_area_query.h
//
// options:
//   PN_SUMMED_AREA_QUERY_KIND   PN_SUMMED_AREA_KIND_MOMENTS (default) or
//   _FLOAT_MOMENTS: the table's kind; one program per kind.

layout(local_size_x = 8, local_size_y = 8) in;

#include "summed_area_query.h"
#include "summed_area.h"

#ifndef PN_SUMMED_AREA_QUERY_KIND
#define PN_SUMMED_AREA_QUERY_KIND PN_SUMMED_AREA_KIND_MOMENTS
#endif

#if PN_SUMMED_AREA_QUERY_KIND == PN_SUMMED_AREA_KIND_FLOAT_MOMENTS
layout(binding = PN_SUMMED_AREA_QUERY_TABLE_BINDING) uniform sampler2D pnTable;
#else
layout(binding = PN_SUMMED_AREA_QUERY_TABLE_BINDING) uniform usampler2D pnTable;
layout(rgba32ui, binding = PN_SUMMED_AREA_QUERY_FIXED_IMAGE) writeonly uniform uimage2D pnSums;
#endif
layout(binding = PN_SUMMED_AREA_QUERY_RECTS_BINDING) uniform sampler2D pnRects;
layout(rgba32f, binding = PN_SUMMED_AREA_QUERY_FLOAT_IMAGE) writeonly uniform image2D pnMoments;

#include "summed_area.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnMoments)))) return;
  vec4 rect = texelFetch(pnRects, p, 0);
#if PN_SUMMED_AREA_QUERY_KIND == PN_SUMMED_AREA_KIND_FLOAT_MOMENTS
  PnSummedAreaMoments m = pnSummedAreaRectFloatMoments(pnTable, ivec2(rect.xy), ivec2(rect.zw));
#else
  uint texels;
  imageStore(pnSums, p, pnSummedAreaRectMomentSums(pnTable, ivec2(rect.xy), ivec2(rect.zw), texels));
  PnSummedAreaMoments m = pnSummedAreaRectMoments(pnTable, ivec2(rect.xy), ivec2(rect.zw));
#endif
  imageStore(pnMoments, p, vec4(m.mean, m.variance, m.texels, 0.0));
}
