// hard_shadow.frag — one hard shadow of the physical reference: whether the
// surface point seen through the pixel is visible from one point of the area
// light, added to the running count of the previous passes (ping-pong: each
// pass reads the last pass's target and writes a new one). The last pass
// divides by the number of samples, so the result is the visible fraction.
//
// Lookup: the receiver's nearest shadow-map texel, the G-buffer's convention
// (pnLightProject, light_model.glsl: texel i spans [i, i + 1));
// a receiver outside the map, or behind the light, is lit. A texel of linear
// depth d occludes receiver depth dP when d < dP - bias (SPEC §3); +Inf and
// NaN ("no occluder") never compare less, so they light the receiver.
// Cost: one shadow-map fetch and one fetch of the previous count per fragment.
//   binding 0: PnHardShadowParams (std140)
//   binding 1: pnShadowMap (R32F, N x N linear depth of the sample point's view)
//   binding 2: pnPreviousCount (R32F, screen-sized, the passes so far)

#include "light_model.glsl"

layout(location = 0) in vec3 pnWorld;
layout(location = 0) out vec4 pnVisibility;

layout(std140, binding = 0) uniform PnHardShadowParams {
  mat4 cameraViewProjection;
  mat4 lightView;
  mat4 lightProjection;
  float mapSize;
  float bias;
  float divisor;
} pnParams;

layout(binding = 1) uniform sampler2D pnShadowMap;
layout(binding = 2) uniform sampler2D pnPreviousCount;

void main() {
  vec3 receiver = pnLightProject(pnParams.lightView, pnParams.lightProjection, pnParams.mapSize, pnWorld);
  float receiverDepth = receiver.z;
  bool occluded = false;
  if (receiverDepth > 0.0) {  // in front of the light (the perspective's clip w is the depth)
    vec2 texel = receiver.xy;
    if (all(greaterThanEqual(texel, vec2(0.0))) && all(lessThan(texel, vec2(pnParams.mapSize)))) {
      // Clamped as well: float rounding of the bounds test must never read outside the map.
      ivec2 last = textureSize(pnShadowMap, 0) - 1;
      float occluder = texelFetch(pnShadowMap, clamp(ivec2(floor(texel)), ivec2(0), last), 0).r;
      occluded = occluder < receiverDepth - pnParams.bias;
    }
  }
  ivec2 pixel = clamp(ivec2(gl_FragCoord.xy), ivec2(0), textureSize(pnPreviousCount, 0) - 1);
  float count = texelFetch(pnPreviousCount, pixel, 0).r + (occluded ? 0.0 : 1.0);
  pnVisibility = vec4(count / pnParams.divisor, 0.0, 0.0, 0.0);
}
