// gbuffer_receiver_plane.glsl — a screen pixel's receiver plane from the
// G-buffer (u, v in texels, light depth, valid): what the shading passes hand
// a technique's receiverPlane argument when their block asks for one.
//
// use:
//   vec2 pnGBufferReceiverPlane(sampler2D gbuffer, ivec2 p, vec4 receiver, PnLight light, float maxTan)
//        maxTan > 0: receiver_plane.glsl's gradient from the four neighbours of pixel p (an entry
//        outside the screen is invalid), its slope clamped to maxTan world units of depth per world
//        unit across (maxTan · the texel's world width per texel); maxTan <= 0 or NaN: 0, no plane.

#ifndef PENUMBRA_PASSES_GBUFFER_RECEIVER_PLANE_GLSL
#define PENUMBRA_PASSES_GBUFFER_RECEIVER_PLANE_GLSL

#include "light_model.glsl"
#include "receiver_plane.glsl"

// A G-buffer entry, invalid (w = 0) outside the screen.
vec4 pn_gBufferEntry(sampler2D gbuffer, ivec2 p) {
  ivec2 n = textureSize(gbuffer, 0);
  return all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, n)) ? texelFetch(gbuffer, p, 0) : vec4(0.0);
}

vec2 pnGBufferReceiverPlane(sampler2D gbuffer, ivec2 p, vec4 receiver, PnLight light, float maxTan) {
  if (!(maxTan > 0.0)) return vec2(0.0);
  float maxSlope = maxTan * pnLightTexelWorld(light, receiver.z);
  return pnReceiverPlaneFromNeighbours(receiver, pn_gBufferEntry(gbuffer, p - ivec2(1, 0)),
                                       pn_gBufferEntry(gbuffer, p + ivec2(1, 0)),
                                       pn_gBufferEntry(gbuffer, p - ivec2(0, 1)),
                                       pn_gBufferEntry(gbuffer, p + ivec2(0, 1)), maxSlope);
}

#endif  // PENUMBRA_PASSES_GBUFFER_RECEIVER_PLANE_GLSL
