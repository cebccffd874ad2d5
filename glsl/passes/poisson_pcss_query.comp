// poisson_pcss_query.comp — poisson_pcss.glsl over a batch of disks.
// Query k: texel k of query image A = (centre x, y, diameter, receiver depth),
//          texel k of query image B = (bias, sample count, rotation cos, sin).
// Result k: (occluders, depth sum, samples, r), r = pnPoissonBlockerMean of the sums at odd query
// indices, pnPoissonOccludedFraction at even ones.
//   bindings and block: poisson_pcss_query.h
// The in-place disk is the constant below — `penumbra poisson --count 16 --seed 1`
// pasted as it prints, as an engine would (the check compares it with the
// generator's points) — or, compiled with PN_QUERY_DISK_IN_BLOCK, the block's
// own array (what the pipeline's pcss_poisson.comp does).

layout(local_size_x = 8, local_size_y = 8) in;

#include "poisson_pcss_query.h"

layout(binding = PN_POISSON_QUERY_MAP_BINDING) uniform sampler2D pnDepthMap;
layout(binding = PN_POISSON_QUERY_A_BINDING) uniform sampler2D pnQueryA;
layout(binding = PN_POISSON_QUERY_B_BINDING) uniform sampler2D pnQueryB;
layout(rgba32f, binding = PN_POISSON_QUERY_RESULT_IMAGE) writeonly uniform image2D pnResult;

#ifdef PN_QUERY_DISK_IN_BLOCK
#define PN_POISSON_DISK_ARRAY pnParams.points
#else
// 16 Poisson-disk samples in the unit disk, minimum distance 0.408536,
// Bridson's algorithm, seed 1 (penumbra poisson).
const vec2 PN_POISSON_DISK[16] = vec2[](
    vec2(-0.207441688, -0.845294714),
    vec2(-0.333447754, -0.406766832),
    vec2(-0.580282748, 0.347517788),
    vec2(0.386596322, -0.357142478),
    vec2(-0.957323909, 0.0350739472),
    vec2(-0.231463432, 0.0759659559),
    vec2(-0.750524163, -0.351998836),
    vec2(-0.474943548, 0.745518923),
    vec2(0.0704084262, 0.641231358),
    vec2(-0.608932853, -0.737210095),
    vec2(0.275796801, -0.813157678),
    vec2(0.606003344, 0.774092376),
    vec2(0.732772112, -0.633546293),
    vec2(0.313952208, 0.0561999418),
    vec2(0.804623067, -0.227169409),
    vec2(0.734715521, 0.378017068)
);
#define PN_POISSON_DISK_ARRAY PN_POISSON_DISK
#endif

#include "poisson_pcss.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResult)))) return;
  vec4 a = texelFetch(pnQueryA, p, 0);
  vec4 b = texelFetch(pnQueryB, p, 0);
  int count = int(b.y);
  PnPoisson s = pnPoissonOcclusionDisk(pnDepthMap, a.xy, a.z, a.w, b.x, count, b.zw);
  float ratio = (p.x % 2 == 1) ? pnPoissonBlockerMean(s) : pnPoissonOccludedFraction(s);
  imageStore(pnResult, p, vec4(s.occluders, s.depthSum, s.samples, ratio));
}
