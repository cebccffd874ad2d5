// vsm_query.comp — vsm.glsl's bounds for a batch of receivers (the check's
// query pass). Query k: texel k of the query image = (texel x, texel y,
// receiver depth, bias); result k = (visibility — the one call pnVsm /
// pnEvsm2 / 4 at the texel's centre —, the Chebyshev bound p alone, p after the
// bleeding reduction, the depth-range bound's code PN_VSM_BOUND_*).
// The kind comes from the parameter block (a check pass: its branches cost
// nothing that matters).
//   bindings and parameter block: vsm_query.h

layout(local_size_x = 8, local_size_y = 8) in;

#include "vsm_query.h"

layout(binding = PN_VSM_QUERY_MOMENTS_BINDING) uniform sampler2D pnMoments;
layout(binding = PN_VSM_QUERY_PYRAMID_BINDING) uniform sampler2DArray pnPyramid;
layout(binding = PN_VSM_QUERY_QUERIES_BINDING) uniform sampler2D pnQueries;
layout(rgba32f, binding = PN_VSM_QUERY_RESULTS_IMAGE) writeonly uniform image2D pnResults;

#include "vsm.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResults)))) return;
  vec4 q = texelFetch(pnQueries, p, 0);
  ivec2 texel = ivec2(q.xy);
  float t = q.z - q.w;
  // The visibility is the module's one call (pnVsm, pnEvsm2, pnEvsm4) for a receiver at the
  // texel's centre, so the check holds the call itself to the reference, not only its parts.
  vec3 receiver = vec3(vec2(texel) + 0.5, q.z);
  vec4 m = pn_vsmFetchMoments(pnMoments, texel);
  float bound = pnVsmDepthRangeBound(pnVsmWindowMinMax(pnPyramid, texel, pnParams.radius), t);
  float chebyshev;
  float visibility;
  if (pnParams.kind == PN_VSM_KIND_EVSM4) {
    chebyshev = pnEvsmBound4(m, t, pnParams.depthRange, pnParams.exponents, pnParams.minVariance);
    visibility = pnEvsm4(pnMoments, pnPyramid, receiver, pnParams.radius, q.w, pnParams.depthRange, pnParams.exponents,
                         pnParams.minVariance, pnParams.bleedingReduction);
  } else if (pnParams.kind == PN_VSM_KIND_EVSM2) {
    chebyshev = pnEvsmBound2(m.xy, t, pnParams.depthRange, pnParams.exponents.x, pnParams.minVariance);
    visibility = pnEvsm2(pnMoments, pnPyramid, receiver, pnParams.radius, q.w, pnParams.depthRange,
                         pnParams.exponents.x, pnParams.minVariance, pnParams.bleedingReduction);
  } else {
    chebyshev = pnVsmChebyshev(m.xy, t, pnParams.minVariance);
    visibility = pnVsm(pnMoments, pnPyramid, receiver, pnParams.radius, q.w, pnParams.minVariance,
                       pnParams.bleedingReduction);
  }
  imageStore(pnResults, p, vec4(visibility, chebyshev, pnVsmReduceBleeding(chebyshev, pnParams.bleedingReduction),
                                bound));
}
