// exports/poisson_pcss_call.glsl — the call exports/poisson_pcss.comp and .frag make: each
// overload of pnPoissonPcss once per receiver of a receiver image (bindings: exports.h,
// poisson_pcss.h; the disks read in place from constants, as poisson_pcss.glsl asks its includer).

#include "poisson_pcss_export.h"

#include "poisson_disks.glsl"
#define PN_POISSON_BLOCKER_DISK PN_EXPORT_BLOCKER_DISK
#define PN_POISSON_FILTER_DISK PN_EXPORT_FILTER_DISK
#include "poisson_pcss.glsl"

#include "receivers.glsl"  // pnExportReceiver, pnExportReceiverPlane
layout(binding = PN_EXPORT_DEPTH_MAP_BINDING) uniform sampler2D pnDepthMap;

#define PN_EXPORT_CALL

float pnExportCall(ivec2 p) {
  vec4 r = pnExportReceiver(p);
  vec2 plane = pnExportReceiverPlane(p);
  PnLight light = PN_LIGHT_FROM_FIELDS(pnExport);
#ifdef PN_EXPORT_ENGINE  // as an engine compiles it (exports.h): the shipped defaults, integration.md's overload
  return pnPoissonPcss(pnDepthMap, light, r.xyz, pnPoissonPcssDefaults(pnExport.bias), vec2(1.0, 0.0));
#endif
  vec2 rotation = pnExport.rotationFromAngle != 0 ? pnPoissonRotation(pnExport.rotationAngle)
                                                  : vec2(pnExport.rotationCos, pnExport.rotationSin);
  // filterScale <= 0: the shipped defaults with the block's bias (pnPoissonPcssDefaults, in the export too).
  PnPoissonPcssSettings settings = pnPoissonPcssDefaults(pnExport.bias);
  if (pnExport.filterScale > 0.0)
    settings = PnPoissonPcssSettings(pnExport.bias, pnExport.filterScale, pnExport.blockerSamples,
                                     pnExport.filterSamples);
  return r.w != 0.0 ? pnPoissonPcss(pnDepthMap, light, r.xyz, plane, settings, rotation)
                    : pnPoissonPcss(pnDepthMap, light, r.xyz, settings, rotation);
}
