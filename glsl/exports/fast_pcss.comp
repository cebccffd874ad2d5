// exports/fast_pcss.comp — the entry `penumbra bundle fast_pcss.glsl --target hlsl|msl` translates
// (runner/shader/export_source.h), and the one the exports check runs on every API. SPIR-V keeps
// only what an entry point reaches, so this entry calls each overload of pnFastPcss once per
// receiver of a receiver image: the export then holds the call and everything it calls, with the
// parameters' names. Its bindings (exports.h, fast_pcss.h) are an example; an engine calls the
// exported function from its own shader with its own resources.

layout(local_size_x = 8, local_size_y = 8) in;

#include "fast_pcss.h"

#ifdef PN_EXPORT_SUM_TABLE  // the exact blocker sums (PN_DEPTH_SUMS_TABLE): the check's exact case
layout(binding = PN_EXPORT_SUM_TABLE_BINDING) uniform highp usampler2D pnDepthSums;
#define PN_TRAVERSAL_SUM_TABLE pnDepthSums
#endif
#include "fast_pcss.glsl"

layout(rgba32f, binding = PN_EXPORT_VISIBILITY_IMAGE) writeonly uniform image2D pnVisibility;
layout(binding = PN_EXPORT_RECEIVERS_BINDING) uniform sampler2D pnReceivers;
layout(binding = PN_EXPORT_PLANES_BINDING) uniform sampler2D pnReceiverPlanes;
layout(binding = PN_EXPORT_DEPTH_MAP_BINDING) uniform sampler2D pnMip;  // the aligned min/max mip chain
layout(binding = PN_EXPORT_SAMPLE_TABLE_BINDING) uniform sampler2D pnSampleTable;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnVisibility)))) return;
  vec4 r = texelFetch(pnReceivers, p, 0);
  vec2 plane = texelFetch(pnReceiverPlanes, p, 0).xy;
  PnLight light = PN_LIGHT_FROM_FIELDS(pnExport);
  // filterScale <= 0: the shipped defaults with the block's bias (pnFastPcssDefaults, in the export too).
  PnFastPcssSettings settings = pnFastPcssDefaults(pnExport.bias);
  if (pnExport.filterScale > 0.0)
    settings = PnFastPcssSettings(pnExport.bias, pnExport.filterScale, pnExport.refineIterations, pnExport.regionMode,
                                  pnExport.leafSide, pnExport.leafDivisor, pnExport.leafMode, pnExport.blockerLeafMode,
                                  pnExport.nodeBudget, pnExport.depthSums, pnExport.grid);
  float v = r.w != 0.0 ? pnFastPcss(pnMip, pnSampleTable, light, r.xyz, plane, p, settings)
                       : pnFastPcss(pnMip, pnSampleTable, light, r.xyz, p, settings);
  imageStore(pnVisibility, p, vec4(v));
}
