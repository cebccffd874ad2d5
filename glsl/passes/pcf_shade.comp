// pcf_shade.comp — the hard shadow with 2×2 bilinear PCF per screen pixel
// (technique `pcf`, seed 003's PCF 2×2 baseline): pcf.glsl's
// pnPcfBilinearVisibility at the pixel's G-buffer position and light depth.
// Pixels that see no surface are lit. Bindings and the block: pcf_shade.h.

layout(local_size_x = 8, local_size_y = 8) in;

#include "pcf_shade.h"

layout(binding = PN_PCF_SHADE_MAP_BINDING) uniform sampler2D pnDepthMap;
layout(binding = PN_PCF_SHADE_GBUFFER_BINDING) uniform sampler2D pnGBuffer;
layout(r32f, binding = PN_PCF_SHADE_VISIBILITY_IMAGE) writeonly uniform image2D pnVisibility;

#include "pcf.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnVisibility)))) return;
  vec4 receiver = texelFetch(pnGBuffer, p, 0);
  float v = receiver.w != 0.0 ? pnPcf(pnDepthMap, receiver.xyz, pnParams.bias) : 1.0;
  imageStore(pnVisibility, p, vec4(v, 0.0, 0.0, 0.0));
}
