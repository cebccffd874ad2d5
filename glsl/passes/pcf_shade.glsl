// pcf_shade.glsl — the hard shadow with 2×2 bilinear PCF per screen pixel
// (technique `pcf`, seed 003's PCF 2×2 baseline): pcf.glsl's
// pnPcfBilinearVisibility at the pixel's G-buffer position and light depth,
// with the receiver plane of its G-buffer neighbours when the block asks for
// one (gbuffer_receiver_plane.glsl). Pixels that see no surface are lit. Bindings and the block: pcf_shade.h.
//
// The body of the compute pass and the fragment shader (shade_pass.h):
// pnShade(p), the visibility of screen pixel p.

#ifndef PENUMBRA_PASSES_PCF_SHADE_GLSL
#define PENUMBRA_PASSES_PCF_SHADE_GLSL

#include "pcf_shade.h"

layout(binding = PN_PCF_SHADE_MAP_BINDING) uniform sampler2D pnDepthMap;
layout(binding = PN_PCF_SHADE_GBUFFER_BINDING) uniform sampler2D pnGBuffer;

#include "pcf.glsl"
#include "gbuffer_receiver_plane.glsl"

float pnShade(ivec2 p) {
  vec4 receiver = texelFetch(pnGBuffer, p, 0);
  if (receiver.w == 0.0) return 1.0;
  vec2 plane = pnGBufferReceiverPlane(pnGBuffer, p, receiver, PN_LIGHT_FROM_FIELDS(pnParams), pnParams.receiverPlaneTan);
  return pnPcf(pnDepthMap, receiver.xyz, plane, pnParams.bias);
}

#endif  // PENUMBRA_PASSES_PCF_SHADE_GLSL
