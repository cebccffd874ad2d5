// pcss_one_call.glsl — a PCSS technique as an engine runs it: per pixel, the
// G-buffer's receiver handed to the technique's one call (pnFastPcss,
// pnPoissonPcss, pnVogelPcss, pnExactPcss or pnHqepcss: PN_PCSS_ONE_CALL), its settings
// from the pipeline's block — or, with PN_PCSS_ENGINE_FORM defined (the runner's rows of a
// technique's shipped settings), as an engine compiles the call: pnXDefaults(bias), every other
// setting a constant, only the bias and the light (and the receiver plane's tangent) from the block.
// The compute pass (pcss_one_call.comp) and the fragment pass
// (pcss_one_call.frag, a full-screen triangle) both return pnOneCallShade.
// Result per pixel: (visibility, Step 4's work, Step 5's work, flags):
// work = traversal nodes (fast) or samples (poisson, vogel), not counted (0) for
// exact PCSS and HQEPCSS, whose calls return the visibility only; flags = 1 when the
// pixel has a search region + 2 when it has a filter region + 4 when it sees
// a surface in front of the light (the staged passes' counts: PcssStats).
// `fetches`: the texel fetches the call made (fast: pnFastPcssEstimate's count;
// poisson, vogel: the samples taken; 0, not counted, for exact PCSS and HQEPCSS)
// — the bench's GPU cost proxy.
//   bindings and blocks: pcss_params.h

#ifndef PENUMBRA_PCSS_ONE_CALL_GLSL
#define PENUMBRA_PCSS_ONE_CALL_GLSL

#include "pcss_params.h"

layout(binding = PN_PCSS_SHADE_GBUFFER_BINDING) uniform sampler2D pnGBuffer;
layout(binding = PN_PCSS_PYRAMID_BINDING) uniform sampler2DArray pnPyramid;
layout(binding = PN_PCSS_MIP_BINDING) uniform sampler2D pnMip;
layout(binding = PN_PCSS_SAMPLE_TABLE_BINDING) uniform sampler2D pnSampleTable;
layout(binding = PN_PCSS_DEPTH_SUMS_BINDING) uniform usampler2D pnDepthSums;
layout(binding = PN_PCSS_DEPTH_MAP_BINDING) uniform sampler2D pnDepthMap;

#define PN_TRAVERSAL_SUM_TABLE pnDepthSums     // fast-table-sums
#define PN_FAST_PCSS_ABLATIONS                 // every switch of the block (fast_pcss.glsl)
#define PN_HQEPCSS_ABLATIONS                   // the node budget too (hqepcss.glsl)
#define PN_POISSON_BLOCKER_DISK pnDisk.points  // read in place
#define PN_POISSON_FILTER_DISK pnFilterDisk.points
#include "pcss_params.glsl"
#include "exact_pcss.glsl"
#include "fast_pcss.glsl"
#include "hqepcss.glsl"
#include "poisson_pcss.glsl"
#include "vogel_pcss.glsl"
#include "gbuffer_receiver_plane.glsl"

#ifndef PN_PCSS_ONE_CALL
#define PN_PCSS_ONE_CALL PN_ONE_CALL_FAST
#endif

float pnOneCallFlags(vec4 searchEntry, vec4 filterEntry) {
  return (pnEntryLit(searchEntry) ? 0.0 : 1.0) + (pnEntryLit(filterEntry) ? 0.0 : 2.0) +
         (searchEntry.x > 0.0 ? 4.0 : 0.0);
}

vec4 pnOneCallShade(ivec2 p, out float fetches) {
  fetches = 0.0;
  vec4 receiver = texelFetch(pnGBuffer, p, 0);
  if (receiver.w == 0.0) return vec4(1.0, 0.0, 0.0, 0.0);  // no surface: lit
  PnLight light = pnPcssLight();
  vec2 plane = pnGBufferReceiverPlane(pnGBuffer, p, receiver, light, pnPcss.receiverPlaneTan);
  if (PN_PCSS_ONE_CALL == PN_ONE_CALL_EXACT) {
    return vec4(pnExactPcss(pnDepthMap, light, receiver.xyz, plane, pnPcss.bias, pnPcss.filterScale), 0.0, 0.0,
                receiver.z > 0.0 ? 4.0 : 0.0);
  }
  if (PN_PCSS_ONE_CALL == PN_ONE_CALL_HQEPCSS) {
#ifdef PN_PCSS_ENGINE_FORM
    PnHqepcssSettings s = pnHqepcssDefaults(pnPcss.bias);
#else
    PnHqepcssSettings s = PnHqepcssSettings(pnPcss.bias, pnPcss.filterScale, pnPcss.refineIterations,
                                            pnPcss.regionMode, pnPcss.leafSide, pnPcss.leafDivisor,
                                            pnPcss.nodeBudget);
#endif
    return vec4(pnHqepcss(pnPyramid, pnDepthMap, light, receiver.xyz, plane, s), 0.0, 0.0, receiver.z > 0.0 ? 4.0 : 0.0);
  }
  if (PN_PCSS_ONE_CALL == PN_ONE_CALL_POISSON) {
#ifdef PN_PCSS_ENGINE_FORM
    PnPoissonPcssSettings s = pnPoissonPcssDefaults(pnPcss.bias);
#else
    PnPoissonPcssSettings s = PnPoissonPcssSettings(pnPcss.bias, pnPcss.filterScale, pnPcss.blockerSamples,
                                                    pnPcss.filterSamples);
#endif
    PnPoissonPcssResult r = pnPoissonPcssEstimate(pnDepthMap, light, receiver.xyz, plane, s, vec2(1.0, 0.0));
    float searched = pnEntryLit(r.searchEntry) ? 0.0 : float(s.blockerSamples);
    float filtered = pnEntryLit(r.filterEntry) ? 0.0 : float(s.filterSamples);
    fetches = searched + filtered;
    return vec4(r.visibility, searched, filtered, pnOneCallFlags(r.searchEntry, r.filterEntry));
  }
  if (PN_PCSS_ONE_CALL == PN_ONE_CALL_VOGEL) {
#ifdef PN_PCSS_ENGINE_FORM
    PnVogelPcssSettings s = pnVogelPcssDefaults(pnPcss.bias);
#else
    PnVogelPcssSettings s = PnVogelPcssSettings(pnPcss.bias, pnPcss.filterScale, pnPcss.blockerSamples,
                                                pnPcss.filterSamples);
#endif
    PnVogelPcssResult r = pnVogelPcssEstimate(pnDepthMap, light, receiver.xyz, plane, p, s);
    float searched = pnEntryLit(r.searchEntry) ? 0.0 : float(s.blockerSamples);
    float filtered = pnEntryLit(r.filterEntry) ? 0.0 : float(s.filterSamples);
    fetches = searched + filtered;
    return vec4(r.visibility, searched, filtered, pnOneCallFlags(r.searchEntry, r.filterEntry));
  }
#ifdef PN_PCSS_ENGINE_FORM
  PnFastPcssSettings s = pnFastPcssDefaults(pnPcss.bias);
#else
  PnFastPcssSettings s = PnFastPcssSettings(pnPcss.bias, pnPcss.filterScale, pnPcss.refineIterations,
                                            pnPcss.regionMode, pnPcss.leafSide, pnPcss.leafDivisor,
                                            pnPcss.leafMode, pnPcss.blockerLeafMode, pnPcss.nodeBudget,
                                            pnPcss.depthSums, pnPcss.grid);
#endif
  PnFastPcssResult r = pnFastPcssEstimate(pnDepthMap, pnMip, pnSampleTable, light, receiver.xyz, plane, p, s);
  fetches = float(r.fetches);
  return vec4(r.visibility, float(r.blockerNodes), float(r.occlusionNodes),
              pnOneCallFlags(r.searchEntry, r.filterEntry));
}

#endif  // PENUMBRA_PCSS_ONE_CALL_GLSL
