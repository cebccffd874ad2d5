// pcss_scan.comp — exact PCSS's Steps 4 and 5: every texel of each entry's
// exact region (pcss_regions.glsl) is fetched and compared, one band of rows
// per dispatch, added to the previous band's sums (ping-pong: GLSL ES has no
// read-write rgba32f images): llvmpipe ends an invocation's
// loops after 65535 iterations in total, which a whole large window would
// exceed (bandRows × ceil(width / 16) stays below it for width <= 8192).
// Result per pixel: (occluders, depth sum, texels, texels fetched).
//   binding 0: pyramid (level 0 = the sanitized map)   binding 3: result (image2D, rgba32f)
//   binding 2: entries (sampler2D, rgba32f)            binding 5: previous band's result (sampler2D)
//   binding 7: PnPcssParams

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2DArray pnPyramid;
layout(binding = 2) uniform sampler2D pnEntries;
layout(binding = 5) uniform sampler2D pnPrevious;
layout(rgba32f, binding = 3) writeonly uniform image2D pnResult;

#include "pcss_params.glsl"
#include "pcss_regions.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResult)))) return;
  vec4 entry = texelFetch(pnEntries, p, 0);
  vec4 sum = pnPcss.bandStart == 0 ? vec4(0.0) : texelFetch(pnPrevious, p, 0);
  if (!pnEntryLit(entry)) {
    PnRect rect = pnEntryRect(entry, pnPyramidMapSize(pnPyramid));
    ivec2 lo = rect.origin, hi = rect.origin + rect.size;
    int rowEnd = min(hi.y, pnPcss.bandStart + pnPcss.bandRows);
    float t = entry.x - pnPcss.bias;
    for (int y = max(lo.y, pnPcss.bandStart); y < rowEnd; ++y) {
      for (int x = lo.x; x < hi.x; x += 16) {
        for (int i = 0; i < 16; ++i) {  // constant trip count: unrolled
          if (x + i < hi.x) {
            float d = pnPyramidFetch(pnPyramid, 0, ivec2(x + i, y)).x;
            if (d < t) sum += vec4(1.0, d, 0.0, 0.0);
          }
        }
      }
      sum.w += float(hi.x - lo.x);
    }
    if (pnPcss.bandStart == 0) sum.z = float(rect.size.x * rect.size.y);
  }
  imageStore(pnResult, p, sum);
}
