// gbuffer.frag — Step 2: for the surface point seen through the pixel, its
// shadow-map position in texels (continuous: texel i spans [i, i + 1)) and its
// linear light depth; w = 1 marks a pixel that sees a surface (cleared to 0).
// Normal offset (Holbert 2011): the point is first moved off its face, along
// the face normal (towards the camera), by normalOffset shadow-map texels at
// its light depth, so that faces seen edge-on by the light (box walls) do not
// shadow themselves in stripes; 0 keeps the surface point itself.
// A cascade's G-buffer keeps only the surfaces in its camera view-depth range.
// The parameter block (shared with gbuffer.vert), its binding and the locations: gbuffer.h.

#include "gbuffer.h"
#include "light_model.glsl"

layout(location = PN_GBUFFER_WORLD_LOCATION) in vec3 pnWorld;
layout(location = PN_SCENE_TARGET_LOCATION) out vec4 pnReceiver;

void main() {
  float viewDepth = dot(pnParams.viewDepthPlane, vec4(pnWorld, 1.0));
  if (!(viewDepth >= pnParams.viewDepthLo && viewDepth < pnParams.viewDepthHi)) {
    pnReceiver = vec4(0.0);  // the nearest surface lies outside this map's range: "no surface" (not discarded,
    return;                  // which would let a farther one through)
  }
  vec3 world = pnWorld;
  if (pnParams.normalOffset > 0.0) {
    vec3 n = normalize(cross(dFdx(pnWorld), dFdy(pnWorld)));
    if (dot(n, pnParams.cameraPosition.xyz - pnWorld) < 0.0) n = -n;
    float depth = -(pnParams.lightView * vec4(pnWorld, 1.0)).z;
    PnLight light = PN_LIGHT_FROM_FIELDS(pnParams);
    world += n * (pnParams.normalOffset * pnLightTexelWorld(light, depth));
  }
  pnReceiver = vec4(pnLightProject(pnParams.lightView, pnParams.lightProjection, pnParams.mapSize, world), 1.0);
}
