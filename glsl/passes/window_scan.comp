// window_scan.comp — the brute-force baseline of traversal_query.comp: every
// texel of each query's region is fetched and compared (PCSS's blocker search
// over the whole window). Same query and result layout as traversal_query.comp
// (bindings and the parameter block: window_scan.h); level 0 of the pyramid is
// the (sanitized) shadow map. On llvmpipe, windows stay exact while
// rows × ceil(width / 8) <= 65535 (any window up to 720²).

layout(local_size_x = 8, local_size_y = 8) in;

#include "window_scan.h"

layout(binding = PN_WINDOW_SCAN_PYRAMID_BINDING) uniform sampler2DArray pnPyramid;
layout(binding = PN_WINDOW_SCAN_A_BINDING) uniform sampler2D pnQueryA;
layout(binding = PN_WINDOW_SCAN_B_BINDING) uniform sampler2D pnQueryB;
layout(rgba32f, binding = PN_WINDOW_SCAN_RESULT_C_BINDING) writeonly uniform image2D pnResultC;
layout(rgba32f, binding = PN_WINDOW_SCAN_RESULT_D_BINDING) writeonly uniform image2D pnResultD;

#include "depth_pyramid.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResultC)))) return;
  vec4 a = texelFetch(pnQueryA, p, 0);
  float t = texelFetch(pnQueryB, p, 0).x - pnParams.bias;
  int n = pnPyramidMapSize(pnPyramid);
  ivec2 lo = clamp(ivec2(a.xy), ivec2(0), ivec2(n));
  ivec2 hi = clamp(ivec2(a.xy + a.zw), lo, ivec2(n));
  float occluders = 0.0;
  float depthSum = 0.0;
  // Eight texels per inner iteration: llvmpipe ends a shader's loops after
  // 65535 iterations in total, which a 256² window would otherwise exceed.
  for (int y = lo.y; y < hi.y; ++y) {
    for (int x = lo.x; x < hi.x; x += 8) {
      for (int i = 0; i < 8; ++i) {  // constant trip count: unrolled
        if (x + i < hi.x) {
          float d = pnPyramidFetch(pnPyramid, 0, ivec2(x + i, y)).x;
          if (d < t) {
            occluders += 1.0;
            depthSum += d;
          }
        }
      }
    }
  }
  ivec2 size = hi - lo;
  imageStore(pnResultC, p, vec4(occluders, depthSum, float(size.x * size.y), 0.0));
  imageStore(pnResultD, p, vec4(0.0, float(size.x * size.y), 0.0, 0.0));
}
