// exports/backprojection_call.glsl — the call exports/backprojection.comp and .frag make:
// pnBackprojection once per receiver of a receiver image, without or with the second layer
// (pnExport.slabs; bindings: exports.h, backprojection_export.h).

#include "backprojection_export.h"
#include "backprojection.glsl"

#include "receivers.glsl"  // pnExportReceiver, pnExportReceiverPlane
layout(binding = PN_EXPORT_DEPTH_MAP_BINDING) uniform sampler2D pnShadowMap;
layout(binding = PN_EXPORT_BACKPROJECTION_MIP_BINDING) uniform sampler2D pnMip;  // the aligned min/max mip chain of it
layout(binding = PN_EXPORT_SECOND_LAYER_BINDING) uniform sampler2D pnSecondMap;
layout(binding = PN_EXPORT_SECOND_MIP_BINDING) uniform sampler2D pnSecondMip;  // the second layer's chain

#define PN_EXPORT_CALL

float pnExportCall(ivec2 p) {
  vec3 r = pnExportReceiver(p).xyz;
  // side <= 0: the shipped defaults (pnBackprojectionDefaults, in the export too).
  PnBackprojectionSettings settings = pnBackprojectionDefaults(pnExport.bias);
#ifdef PN_EXPORT_ENGINE  // as an engine compiles it (exports.h): the shipped defaults
#if defined(PN_EXPORT_BACKPROJECTION_LAYERS) && PN_EXPORT_BACKPROJECTION_LAYERS == 2
  return pnBackprojection(pnShadowMap, pnMip, pnSecondMap, pnSecondMip, PN_LIGHT_FROM_FIELDS(pnExport), r, settings);
#else
  return pnBackprojection(pnShadowMap, pnMip, PN_LIGHT_FROM_FIELDS(pnExport), r, settings);
#endif
#endif
  if (pnExport.side > 0)
    settings = PnBackprojectionSettings(pnExport.bias, pnExport.side, pnExport.tolerance, pnExport.budget, pnExport.gap,
                                        pnExport.thickness);
  if (pnExport.slabs != 0) return pnBackprojection(pnShadowMap, pnMip, pnSecondMap, pnSecondMip, PN_LIGHT_FROM_FIELDS(pnExport), r, settings);
  return pnBackprojection(pnShadowMap, pnMip, PN_LIGHT_FROM_FIELDS(pnExport), r, settings);
}
