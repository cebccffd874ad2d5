// exports/vsm_call.glsl — the calls exports/vsm.comp and .frag make: pnVsm, pnEvsm2 or pnEvsm4
// (the block's kind) once per receiver of a receiver image (bindings: exports.h, vsm.h).

#include "vsm_export.h"
#include "vsm.glsl"

#include "receivers.glsl"  // pnExportReceiver, pnExportReceiverPlane
layout(binding = PN_EXPORT_MOMENTS_BINDING) uniform sampler2D pnMoments;
layout(binding = PN_EXPORT_VSM_PYRAMID_BINDING) uniform sampler2DArray pnPyramid;

#define PN_EXPORT_CALL

float pnExportCall(ivec2 p) {
  vec3 r = pnExportReceiver(p).xyz;
  vec2 range = vec2(pnExport.depthNear, pnExport.depthFar);
#ifdef PN_EXPORT_VSM_KIND  // one call compiled (penumbra isa): the kind a constant
  const int kind = PN_EXPORT_VSM_KIND;
#else
  int kind = pnExport.kind;
#endif
  if (kind == PN_EXPORT_EVSM2)
    return pnEvsm2(pnMoments, pnPyramid, r, pnExport.radius, pnExport.bias, range, pnExport.evsm2Exponent,
                   pnExport.minVariance, pnExport.bleedingReduction);
  if (kind == PN_EXPORT_EVSM4)
    return pnEvsm4(pnMoments, pnPyramid, r, pnExport.radius, pnExport.bias, range,
                   vec2(pnExport.evsm4Positive, pnExport.evsm4Negative), pnExport.minVariance,
                   pnExport.bleedingReduction);
  return pnVsm(pnMoments, pnPyramid, r, pnExport.radius, pnExport.bias, pnExport.minVariance,
               pnExport.bleedingReduction);
}
