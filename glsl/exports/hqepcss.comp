// exports/hqepcss.comp — the entry `penumbra bundle hqepcss.glsl --target hlsl|msl` translates
// (runner/shader/export_source.h), and the one the exports check runs on every API. SPIR-V keeps
// only what an entry point reaches, so this entry calls each overload of pnHqepcss once per
// receiver of a receiver image: the export then holds the call and everything it calls, with the
// parameters' names. Its bindings (exports.h, hqepcss.h) are an example; an engine calls the
// exported function from its own shader with its own resources.

layout(local_size_x = 8, local_size_y = 8) in;

#include "hqepcss.h"
#include "hqepcss.glsl"

layout(rgba32f, binding = PN_EXPORT_VISIBILITY_IMAGE) writeonly uniform image2D pnVisibility;
layout(binding = PN_EXPORT_RECEIVERS_BINDING) uniform sampler2D pnReceivers;
layout(binding = PN_EXPORT_PLANES_BINDING) uniform sampler2D pnReceiverPlanes;
layout(binding = PN_EXPORT_PYRAMID_BINDING) uniform sampler2DArray pnPyramid;  // the decreased depth pyramid
layout(binding = PN_EXPORT_DEPTH_MAP_BINDING) uniform sampler2D pnDepthMap;    // the shadow map, linear depth

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnVisibility)))) return;
  vec4 r = texelFetch(pnReceivers, p, 0);
  vec2 plane = texelFetch(pnReceiverPlanes, p, 0).xy;
  PnLight light = PN_LIGHT_FROM_FIELDS(pnExport);
  // filterScale <= 0: the shipped defaults with the block's bias (pnHqepcssDefaults, in the export too).
  PnHqepcssSettings settings = pnHqepcssDefaults(pnExport.bias);
  if (pnExport.filterScale > 0.0)
    settings = PnHqepcssSettings(pnExport.bias, pnExport.filterScale, pnExport.refineIterations, pnExport.regionMode,
                                 pnExport.leafSide, pnExport.leafDivisor, pnExport.nodeBudget);
  float v = r.w != 0.0 ? pnHqepcss(pnPyramid, pnDepthMap, light, r.xyz, plane, settings)
                       : pnHqepcss(pnPyramid, pnDepthMap, light, r.xyz, settings);
  imageStore(pnVisibility, p, vec4(v));
}
