// exports/pcf_call.glsl — the call exports/pcf.comp and .frag make: each overload of pnPcf once
// per receiver of a receiver image (bindings: exports.h, pcf.h).

#include "pcf_export.h"
#include "pcf.glsl"

#include "receivers.glsl"  // pnExportReceiver, pnExportReceiverPlane
layout(binding = PN_EXPORT_DEPTH_MAP_BINDING) uniform sampler2D pnDepthMap;

#define PN_EXPORT_CALL

float pnExportCall(ivec2 p) {
  vec4 r = pnExportReceiver(p);
#ifdef PN_EXPORT_ENGINE  // as an engine compiles it (exports.h): integration.md's overload
  return pnPcf(pnDepthMap, r.xyz, pnExport.bias);
#endif
  vec2 plane = pnExportReceiverPlane(p);
  return r.w != 0.0 ? pnPcf(pnDepthMap, r.xyz, plane, pnExport.bias) : pnPcf(pnDepthMap, r.xyz, pnExport.bias);
}
