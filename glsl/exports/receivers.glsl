// exports/receivers.glsl — the receiver image every export entry reads (exports.h): receiver k
// of a batch at texel k, its (u, v, light depth) and whether it goes through the call's
// receiverPlane overload, and that plane (du, dv). Included by each exports/X_call.glsl.

#ifndef PENUMBRA_EXPORTS_RECEIVERS_GLSL
#define PENUMBRA_EXPORTS_RECEIVERS_GLSL

#include "exports.h"

layout(binding = PN_EXPORT_RECEIVERS_BINDING) uniform sampler2D pnReceivers;
layout(binding = PN_EXPORT_PLANES_BINDING) uniform sampler2D pnReceiverPlanes;

// (u, v, light depth, 1: with the receiver plane) of the receiver at `p`.
vec4 pnExportReceiver(ivec2 p) {
  return texelFetch(pnReceivers, p, 0);
}

// Its receiver plane: the light depth per texel (du, dv).
vec2 pnExportReceiverPlane(ivec2 p) {
  return texelFetch(pnReceiverPlanes, p, 0).xy;
}

#endif  // PENUMBRA_EXPORTS_RECEIVERS_GLSL
