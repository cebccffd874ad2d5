// exports/savsm_call.glsl — the call exports/savsm.comp and .frag make: pnSavsm once per
// receiver of a receiver image (bindings: exports.h, savsm.h).

#include "savsm_export.h"
#include "savsm.glsl"

#include "receivers.glsl"  // pnExportReceiver, pnExportReceiverPlane
layout(binding = PN_EXPORT_MOMENT_TABLE_BINDING) uniform PN_SAVSM_TABLE_SAMPLER pnTable;
layout(binding = PN_EXPORT_MIP_BINDING) uniform sampler2D pnMip;

#define PN_EXPORT_CALL

float pnExportCall(ivec2 p) {
  vec4 r = pnExportReceiver(p);
#ifdef PN_EXPORT_ENGINE  // as an engine compiles it (exports.h): the runner's blocker and bound as constants
  PnSavsmSettings settings = PnSavsmSettings(pnExport.bias, pnExport.filterScale, pnExport.minVariance,
                                             pnExport.bleedingReduction, PN_SAVSM_BLOCKER_MIN, true);
#else
  PnSavsmSettings settings = PnSavsmSettings(pnExport.bias, pnExport.filterScale, pnExport.minVariance,
                                             pnExport.bleedingReduction, pnExport.blockerMode, pnExport.bound != 0);
  if (pnExport.filterScale <= 0.0) settings = pnSavsmDefaults(pnExport.bias);  // the check's defaults run
#endif
  return pnSavsm(pnTable, pnMip, PN_LIGHT_FROM_FIELDS(pnExport), r.xyz, vec2(pnExport.unitNear, pnExport.unitScale),
                 settings);
}
