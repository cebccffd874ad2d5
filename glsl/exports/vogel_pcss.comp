// exports/vogel_pcss.comp — the entry `penumbra bundle vogel_pcss.glsl --target hlsl|msl` translates
// (runner/shader/export_source.h). SPIR-V keeps only what an entry point reaches, so this entry
// calls each overload of pnVogelPcss once per receiver of a receiver image: the export then holds the call and
// everything it calls, with the parameters' names. Its bindings are an example; an engine calls
// the exported function from its own shader with its own resources.

layout(local_size_x = 8, local_size_y = 8) in;

#include "vogel_pcss.glsl"

layout(rgba32f, binding = 0) writeonly uniform image2D pnVisibility;
layout(binding = 1) uniform sampler2D pnReceivers;       // (u, v, light depth, 1: with the receiver plane)
layout(binding = 2) uniform sampler2D pnReceiverPlanes;  // (du, dv): light depth per texel
layout(binding = 3) uniform sampler2D pnDepthMap;  // the shadow map, linear depth
layout(std140, binding = 4) uniform PnVogelPcssExport {
  PnLight light;
  PnVogelPcssSettings settings;
} pnExport;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnVisibility)))) return;
  vec4 r = texelFetch(pnReceivers, p, 0);
  vec2 plane = texelFetch(pnReceiverPlanes, p, 0).xy;
  // filterScale 0: the shipped defaults with the block's bias (pnVogelPcssDefaults, in the export too).
  PnVogelPcssSettings settings = pnVogelPcssDefaults(pnExport.settings.bias);
  if (pnExport.settings.filterScale > 0.0) settings = pnExport.settings;
  float v = r.w != 0.0 ? pnVogelPcss(pnDepthMap, pnExport.light, r.xyz, plane, p, settings)
                       : pnVogelPcss(pnDepthMap, pnExport.light, r.xyz, p, settings);
  imageStore(pnVisibility, p, vec4(v));
}
