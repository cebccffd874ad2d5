// savsm_query.comp — savsm.glsl's estimate for a batch of receivers, every
// step's value and the number of texel fetches each took (the check's
// constant-cost case): PN_ON_TEXEL_FETCH counts the table's and the mip chain's
// fetches. Query k: texel k of the input = (u, v, light depth, -); result k:
// texel k of the four images (savsm_params.h).
//
// options: PN_SAVSM_TABLE, as savsm_shade.comp.

layout(local_size_x = 8, local_size_y = 8) in;

int pnFetches = 0;
#define PN_ON_TEXEL_FETCH() pnFetches += 1

#include "savsm_params.h"
#include "savsm.glsl"

layout(binding = PN_SAVSM_TABLE_BINDING) uniform PN_SAVSM_TABLE_SAMPLER pnTable;
layout(binding = PN_SAVSM_MIP_BINDING) uniform sampler2D pnMip;
layout(binding = PN_SAVSM_INPUT_BINDING) uniform sampler2D pnReceivers;
layout(rgba32f, binding = PN_SAVSM_SEARCH_IMAGE) writeonly uniform image2D pnSearch;
layout(rgba32f, binding = PN_SAVSM_FILTER_IMAGE) writeonly uniform image2D pnFilter;
layout(rgba32f, binding = PN_SAVSM_BLOCKER_IMAGE) writeonly uniform image2D pnBlocker;
layout(rgba32f, binding = PN_SAVSM_RESULT_IMAGE) writeonly uniform image2D pnResult;

#include "savsm_params.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnResult)))) return;
  pnFetches = 0;
  vec4 q = texelFetch(pnReceivers, p, 0);
  PnSavsm s = pnSavsmEstimate(pnTable, pnMip, pnSavsmParamsLight(), q.xyz, pnParams.unitRange,
                              pnSavsmParamsSettings());
  imageStore(pnSearch, p, vec4(vec2(s.searchRect.origin), vec2(s.searchRect.size)));
  imageStore(pnFilter, p, vec4(vec2(s.filterRect.origin), vec2(s.filterRect.size)));
  imageStore(pnBlocker, p, vec4(s.blocker, s.hasBlocker ? 1.0 : 0.0, s.filterSide, float(pnFetches)));
  // The visibility is the module's one call, pnSavsm (after the fetches are stored: it fetches
  // again), so the check holds the call itself to the reference, not only pnSavsmEstimate.
  float visibility = pnSavsm(pnTable, pnMip, pnSavsmParamsLight(), q.xyz, pnParams.unitRange, pnSavsmParamsSettings());
  imageStore(pnResult, p, vec4(s.mean, s.variance, s.chebyshev, visibility));
}
