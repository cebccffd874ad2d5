// light_model_query.comp — light_model.glsl over a batch of (receiver depth, blocker depth).
// Result k: (blocker window texels, search width texels, penumbra world, penumbra texels).
//   binding 0: queries (sampler2D, RGBA32F: receiver, blocker, -, -)   binding 2: results (image2D, rgba32f)
//   binding 3: PnLightParams (std140)

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D pnQueries;
layout(rgba32f, binding = 2) writeonly uniform image2D pnResults;
layout(std140, binding = 3) uniform PnLightParams {
  float width;
  float near;
  float nearPlaneWidth;
  float mapSize;
} pnParams;

#include "light_model.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResults)))) return;
  vec4 q = texelFetch(pnQueries, p, 0);
  PnLight light = PnLight(pnParams.width, pnParams.near, pnParams.nearPlaneWidth, pnParams.mapSize);
  imageStore(pnResults, p, vec4(pnLightBlockerWindowTexels(light, q.x, q.y), pnLightSearchWidthTexels(light, q.x),
                                pnLightPenumbraWorld(light, q.x, q.y), pnLightPenumbraTexels(light, q.x, q.y)));
}
