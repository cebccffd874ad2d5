// exports/hqepcss_call.glsl — the call exports/hqepcss.comp and .frag make: each overload of
// pnHqepcss once per receiver of a receiver image (bindings: exports.h, hqepcss.h).

#include "hqepcss_export.h"
// The block's node budget — but not in the engine's build (the shipped walk alone).
#ifndef PN_EXPORT_ENGINE
#define PN_HQEPCSS_ABLATIONS
#endif
#include "hqepcss.glsl"

#include "receivers.glsl"  // pnExportReceiver, pnExportReceiverPlane
layout(binding = PN_EXPORT_PYRAMID_BINDING) uniform sampler2DArray pnPyramid;  // the decreased depth pyramid
layout(binding = PN_EXPORT_DEPTH_MAP_BINDING) uniform sampler2D pnDepthMap;    // the shadow map, linear depth

#define PN_EXPORT_CALL

float pnExportCall(ivec2 p) {
  vec4 r = pnExportReceiver(p);
  vec2 plane = pnExportReceiverPlane(p);
  PnLight light = PN_LIGHT_FROM_FIELDS(pnExport);
#ifdef PN_EXPORT_ENGINE  // as an engine compiles it (exports.h): the shipped defaults, integration.md's overload
  return pnHqepcss(pnPyramid, pnDepthMap, light, r.xyz, pnHqepcssDefaults(pnExport.bias));
#endif
  // filterScale <= 0: the shipped defaults with the block's bias (pnHqepcssDefaults, in the export too).
  PnHqepcssSettings settings = pnHqepcssDefaults(pnExport.bias);
  if (pnExport.filterScale > 0.0)
    settings = PnHqepcssSettings(pnExport.bias, pnExport.filterScale, pnExport.refineIterations, pnExport.regionMode,
                                 pnExport.leafSide, pnExport.leafDivisor, pnExport.nodeBudget);
  return r.w != 0.0 ? pnHqepcss(pnPyramid, pnDepthMap, light, r.xyz, plane, settings)
                    : pnHqepcss(pnPyramid, pnDepthMap, light, r.xyz, settings);
}
