// light_depth_query.comp — light_model.glsl's pnLightDepthFromDepthBuffer over a
// batch of depth-buffer values, for both clip-range conventions, and pnLightProject of a batch of
// world points. Query k: (depth-buffer value, world x, y, z).
// Result k: (linear depth as OpenGL's [-1, 1] clip range wrote it, as a [0, 1] clip range did,
// pnLightProject's u and v of the world point).
// Bindings and the projection block: light_depth_query.h.

layout(local_size_x = 8, local_size_y = 8) in;

#include "light_depth_query.h"

layout(binding = PN_LIGHT_DEPTH_QUERY_QUERIES_BINDING) uniform sampler2D pnQueries;
layout(rgba32f, binding = PN_LIGHT_DEPTH_QUERY_RESULTS_BINDING) writeonly uniform image2D pnResults;

#include "light_model.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResults)))) return;
  vec4 q = texelFetch(pnQueries, p, 0);
  vec3 projected = pnLightProject(pnParams.lightView, pnParams.lightProjection, pnParams.mapSize, q.yzw);
  imageStore(pnResults, p, vec4(pnLightDepthFromDepthBuffer(pnParams.lightProjection, q.x, false),
                                pnLightDepthFromDepthBuffer(pnParams.lightProjection, q.x, true), projected.xy));
}
