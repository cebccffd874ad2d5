// exports/fast_pcss_call.glsl — the call exports/fast_pcss.comp and .frag make: each overload of
// pnFastPcss once per receiver of a receiver image (bindings: exports.h, fast_pcss.h).

#include "fast_pcss_export.h"

#ifdef PN_EXPORT_SUM_TABLE  // the exact blocker sums (PN_DEPTH_SUMS_TABLE): the check's exact case
layout(binding = PN_EXPORT_SUM_TABLE_BINDING) uniform highp usampler2D pnDepthSums;
#define PN_TRAVERSAL_SUM_TABLE pnDepthSums
#endif
// The shipped walk alone, as an engine's shader holds it — what `bundle --target hlsl|msl` exports
// (issue 54's new user found the ablations in the HLSL). With PN_EXPORT_ABLATIONS (the exports
// check's ablation cases) the block's settings reach every ablation too.
#if !defined(PN_EXPORT_ENGINE) && defined(PN_EXPORT_ABLATIONS)
#define PN_FAST_PCSS_ABLATIONS
#endif
#include "fast_pcss.glsl"

#include "receivers.glsl"  // pnExportReceiver, pnExportReceiverPlane
layout(binding = PN_EXPORT_DEPTH_MAP_BINDING) uniform sampler2D pnShadowMap;
layout(binding = PN_EXPORT_FAST_MIP_BINDING) uniform sampler2D pnMip;  // the aligned min/max mip chain of it
layout(binding = PN_EXPORT_SAMPLE_TABLE_BINDING) uniform sampler2D pnSampleTable;

#define PN_EXPORT_CALL

float pnExportCall(ivec2 p) {
  vec4 r = pnExportReceiver(p);
  vec2 plane = pnExportReceiverPlane(p);
  PnLight light = PN_LIGHT_FROM_FIELDS(pnExport);
#ifdef PN_EXPORT_ENGINE  // as an engine compiles it (exports.h): the shipped defaults, integration.md's overload
  return pnFastPcss(pnShadowMap, pnMip, pnSampleTable, light, r.xyz, p, pnFastPcssDefaults(pnExport.bias));
#endif
  // filterScale <= 0: the shipped defaults with the block's bias (pnFastPcssDefaults, in the export too).
  PnFastPcssSettings settings = pnFastPcssDefaults(pnExport.bias);
  if (pnExport.filterScale > 0.0)
    settings = PnFastPcssSettings(pnExport.bias, pnExport.filterScale, pnExport.refineIterations, pnExport.regionMode,
                                  pnExport.leafSide, pnExport.leafDivisor, pnExport.leafMode, pnExport.blockerLeafMode,
                                  pnExport.nodeBudget, pnExport.depthSums, pnExport.grid);
  return r.w != 0.0 ? pnFastPcss(pnShadowMap, pnMip, pnSampleTable, light, r.xyz, plane, p, settings)
                    : pnFastPcss(pnShadowMap, pnMip, pnSampleTable, light, r.xyz, p, settings);
}
