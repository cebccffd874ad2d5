// exports/vogel_pcss_call.glsl — the call exports/vogel_pcss.comp and .frag make: each overload
// of pnVogelPcss once per receiver of a receiver image, the pixel the receiver's texel
// (bindings: exports.h, vogel_pcss.h).

#include "vogel_pcss_export.h"
#include "vogel_pcss.glsl"

#include "receivers.glsl"  // pnExportReceiver, pnExportReceiverPlane
layout(binding = PN_EXPORT_DEPTH_MAP_BINDING) uniform sampler2D pnDepthMap;

#define PN_EXPORT_CALL

float pnExportCall(ivec2 p) {
  vec4 r = pnExportReceiver(p);
  vec2 plane = pnExportReceiverPlane(p);
  PnLight light = PN_LIGHT_FROM_FIELDS(pnExport);
#ifdef PN_EXPORT_ENGINE  // as an engine compiles it (exports.h): the shipped defaults, integration.md's overload
  return pnVogelPcss(pnDepthMap, light, r.xyz, p, pnVogelPcssDefaults(pnExport.bias));
#endif
  // filterScale <= 0: the shipped defaults with the block's bias (pnVogelPcssDefaults, in the export too).
  PnVogelPcssSettings settings = pnVogelPcssDefaults(pnExport.bias);
  if (pnExport.filterScale > 0.0)
    settings = PnVogelPcssSettings(pnExport.bias, pnExport.filterScale, pnExport.blockerSamples,
                                   pnExport.filterSamples);
  return r.w != 0.0 ? pnVogelPcss(pnDepthMap, light, r.xyz, plane, p, settings)
                    : pnVogelPcss(pnDepthMap, light, r.xyz, p, settings);
}
