// exports/exact_pcss_call.glsl — the call exports/exact_pcss.comp and .frag make: each overload
// of pnExactPcss once per receiver of a receiver image (bindings: exports.h, exact_pcss.h).

#include "exact_pcss_export.h"
#include "exact_pcss.glsl"

#include "receivers.glsl"  // pnExportReceiver, pnExportReceiverPlane
layout(binding = PN_EXPORT_DEPTH_MAP_BINDING) uniform sampler2D pnDepthMap;

#define PN_EXPORT_CALL

float pnExportCall(ivec2 p) {
  vec4 r = pnExportReceiver(p);
  vec2 plane = pnExportReceiverPlane(p);
  PnLight light = PN_LIGHT_FROM_FIELDS(pnExport);
#ifdef PN_EXPORT_ENGINE  // as an engine compiles it (exports.h): integration.md's overload
  return pnExactPcss(pnDepthMap, light, r.xyz, pnExport.bias, pnExport.filterScale);
#endif
  return r.w != 0.0 ? pnExactPcss(pnDepthMap, light, r.xyz, plane, pnExport.bias, pnExport.filterScale)
                    : pnExactPcss(pnDepthMap, light, r.xyz, pnExport.bias, pnExport.filterScale);
}
