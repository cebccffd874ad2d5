// exports/pcf_call.glsl — the call exports/pcf.comp and .frag make: each overload of pnPcf once
// per receiver of a receiver image (bindings: exports.h, pcf.h).

#include "pcf.h"
#include "pcf.glsl"

layout(binding = PN_EXPORT_RECEIVERS_BINDING) uniform sampler2D pnReceivers;
layout(binding = PN_EXPORT_PLANES_BINDING) uniform sampler2D pnReceiverPlanes;
layout(binding = PN_EXPORT_DEPTH_MAP_BINDING) uniform sampler2D pnDepthMap;

#define PN_EXPORT_CALL

float pnExportCall(ivec2 p) {
  vec4 r = texelFetch(pnReceivers, p, 0);
  vec2 plane = texelFetch(pnReceiverPlanes, p, 0).xy;
  return r.w != 0.0 ? pnPcf(pnDepthMap, r.xyz, plane, pnExport.bias) : pnPcf(pnDepthMap, r.xyz, pnExport.bias);
}
