// traversal_query.comp — traversal.glsl over a batch of receivers.
// Query k: texel k of query image A = (region origin x, y, region width, height),
//          texel k of query image B = (receiver depth, screen pixel x, y, 0).
// Result k: image C = (occluders, depth sum, texels, 0), image D = (nodes, fetches, 0, 0).
//   binding 0: pyramid (sampler2DArray)      binding 3: result C (image2D, rgba32f)
//   binding 1: sample table (sampler2D)      binding 4: result D (image2D, rgba32f)
//   binding 2: query A (sampler2D)           binding 5: query B (sampler2D)
//   binding 6: PnTraversalQueryParams (std140)

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2DArray pnPyramid;
layout(binding = 1) uniform sampler2D pnSampleTable;
layout(binding = 2) uniform sampler2D pnQueryA;
layout(binding = 5) uniform sampler2D pnQueryB;
layout(rgba32f, binding = 3) writeonly uniform image2D pnResultC;
layout(rgba32f, binding = 4) writeonly uniform image2D pnResultD;
layout(std140, binding = 6) uniform PnTraversalQueryParams {
  float bias;
  int leafSide;
  int leafMode;
  int nodeBudget;
} pnParams;

#include "traversal.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResultC)))) return;
  vec4 a = texelFetch(pnQueryA, p, 0);
  vec4 b = texelFetch(pnQueryB, p, 0);
  PnTraversal r = pnTraverseRegion(pnPyramid, pnSampleTable, ivec2(a.xy), ivec2(a.zw), b.x, pnParams.bias,
                                   pnParams.leafSide, pnParams.leafMode, pnParams.nodeBudget, ivec2(b.yz));
  imageStore(pnResultC, p, vec4(r.occluders, r.depthSum, r.texels, 0.0));
  imageStore(pnResultD, p, vec4(float(r.nodes), float(r.fetches), 0.0, 0.0));
}
