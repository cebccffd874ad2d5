// exports/pcf.comp — the entry `penumbra bundle pcf.glsl --target hlsl|msl` translates
// (runner/shader/export_source.h), and the one the exports check runs on every API. SPIR-V keeps
// only what an entry point reaches, so this entry calls each overload of pnPcf once per receiver
// of a receiver image: the export then holds the call and everything it calls, with the
// parameters' names. Its bindings (exports.h) are an example; an engine calls the exported
// function from its own shader with its own resources.

layout(local_size_x = 8, local_size_y = 8) in;

#include "pcf.h"
#include "pcf.glsl"

layout(rgba32f, binding = PN_EXPORT_VISIBILITY_IMAGE) writeonly uniform image2D pnVisibility;
layout(binding = PN_EXPORT_RECEIVERS_BINDING) uniform sampler2D pnReceivers;
layout(binding = PN_EXPORT_PLANES_BINDING) uniform sampler2D pnReceiverPlanes;
layout(binding = PN_EXPORT_DEPTH_MAP_BINDING) uniform sampler2D pnDepthMap;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnVisibility)))) return;
  vec4 r = texelFetch(pnReceivers, p, 0);
  vec2 plane = texelFetch(pnReceiverPlanes, p, 0).xy;
  float v = r.w != 0.0 ? pnPcf(pnDepthMap, r.xyz, plane, pnExport.bias) : pnPcf(pnDepthMap, r.xyz, pnExport.bias);
  imageStore(pnVisibility, p, vec4(v));
}
