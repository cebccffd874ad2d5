// sample_table_query.comp — the sample_table.glsl selection over a batch of queries.
// Query k (texel k of the query image): (pixel x, pixel y, region side, i).
// Result A: (k, first column, last column, set).
// Result B: (column of the i-th selected sample, texel x, texel y, 0) for that
//           sample scaled to a region of the given side at origin (0, 0).
// Bindings: sample_table_query.h.

layout(local_size_x = 8, local_size_y = 8) in;

#include "sample_table_query.h"

layout(binding = PN_SAMPLE_TABLE_QUERY_QUERIES_BINDING) uniform sampler2D pnQueries;
layout(binding = PN_SAMPLE_TABLE_QUERY_TABLE_BINDING) uniform sampler2D pnSampleTable;
layout(rgba32f, binding = PN_SAMPLE_TABLE_QUERY_RESULT_A_BINDING) writeonly uniform image2D pnResultA;
layout(rgba32f, binding = PN_SAMPLE_TABLE_QUERY_RESULT_B_BINDING) writeonly uniform image2D pnResultB;

#include "sample_table.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResultA)))) return;
  vec4 q = texelFetch(pnQueries, p, 0);
  ivec2 pixel = ivec2(q.xy);
  int side = int(q.z);
  int k = pnSampleGroupLog4(side);
  int first = pnSampleFirstColumn(k);
  int set = pnSampleSet(pixel);
  int column = first + min(int(q.w), pnSampleCount(k) - 1);
  ivec2 texel = pnSampleTexel(pnSample(pnSampleTable, column, set), ivec2(0), ivec2(side));
  imageStore(pnResultA, p, vec4(float(k), float(first), float(pnSampleLastColumn(k)), float(set)));
  imageStore(pnResultB, p, vec4(float(column), vec2(texel), 0.0));
}
