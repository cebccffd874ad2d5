// light_model.glsl — the area light and its widths in shadow-map texels.
//
// description:
//   SPEC §4.7: a square area light of world width w_L at the shadow map's
//   viewpoint, facing along its axis; the shadow map is a perspective view
//   from the light's centre with near plane n, far plane f and a near-plane
//   world width W_n = 2 n tan(fov / 2), N×N texels, storing linear depth
//   (distance along the axis). By similar triangles:
//   - blockers at depth z that can shadow a receiver at depth dP lie in a
//     window of world width w_L (dP - z) / dP at depth z, which projects to
//       blockerWindowTexels(dP, z) = w_L (dP - z) / dP · (n / z) / W_n · N
//     (the blocker search: z = n for PCSS's initial search, z = zmin when
//     the pyramid has refined it — HQEPCSS);
//   - the penumbra of Eq. (1) is a world width at the receiver,
//       s_p = w_L (dP - dz) / dz   (dz: the blocker mean),
//     which projects to penumbraTexels = s_p · (n / dP) / W_n · N.
//   (NVIDIA's filterRadiusUV = penumbraRatio · lightSizeUV · near / zReceiver
//   is the second formula as a radius in UV.) Every technique takes its
//   widths from here; runner/scene/light_model.h is the same on the CPU.
//   Degenerate inputs give 0 texels (a hard shadow), never NaN: a zero light,
//   a receiver or blocker at or before the near plane, a blocker at or behind
//   the receiver, non-finite values.
//
// use:
//   PnLight { float width; float near; float nearPlaneWidth; float mapSize; }
//   float pnLightBlockerWindowTexels(PnLight light, float receiverDepth, float blockerDepth)
//   float pnLightSearchWidthTexels(PnLight light, float receiverDepth)     = window for z = near
//   float pnLightPenumbraWorld(PnLight light, float receiverDepth, float blockerDepth)
//   float pnLightPenumbraTexels(PnLight light, float receiverDepth, float blockerDepth)
//   vec3  pnLightProject(mat4 lightView, mat4 lightProjection, float mapSize, vec3 world)
//         a world point in the shadow map's terms: (u, v) in texels (continuous, texel i
//         spans [i, i + 1)) and its linear light depth; depth <= 0: behind the light
//         (u, v then meaningless). What the G-buffer stores and a hard shadow looks up.
//
// cost: a few ALU operations.

#ifndef PENUMBRA_LIGHT_MODEL_GLSL
#define PENUMBRA_LIGHT_MODEL_GLSL

struct PnLight {
  float width;           // w_L, world units
  float near;            // n, world units along the axis
  float nearPlaneWidth;  // W_n = 2 n tan(fov / 2)
  float mapSize;         // N, texels
};

// x when finite and positive, else 0.
float pnLightPositiveOrZero(float x) {
  return (x > 0.0 && !isinf(x)) ? x : 0.0;
}

float pnLightBlockerWindowTexels(PnLight light, float receiverDepth, float blockerDepth) {
  if (!(receiverDepth > blockerDepth) || !(blockerDepth >= light.near) || !(light.near > 0.0) ||
      !(light.nearPlaneWidth > 0.0))
    return 0.0;
  float world = light.width * (receiverDepth - blockerDepth) / receiverDepth;
  return pnLightPositiveOrZero(world * (light.near / blockerDepth) / light.nearPlaneWidth * light.mapSize);
}

float pnLightSearchWidthTexels(PnLight light, float receiverDepth) {
  return pnLightBlockerWindowTexels(light, receiverDepth, light.near);
}

float pnLightPenumbraWorld(PnLight light, float receiverDepth, float blockerDepth) {
  if (!(receiverDepth > blockerDepth) || !(blockerDepth > 0.0)) return 0.0;
  return pnLightPositiveOrZero(light.width * (receiverDepth - blockerDepth) / blockerDepth);
}

float pnLightPenumbraTexels(PnLight light, float receiverDepth, float blockerDepth) {
  if (!(receiverDepth >= light.near) || !(light.near > 0.0) || !(light.nearPlaneWidth > 0.0)) return 0.0;
  float world = pnLightPenumbraWorld(light, receiverDepth, blockerDepth);
  return pnLightPositiveOrZero(world * (light.near / receiverDepth) / light.nearPlaneWidth * light.mapSize);
}

vec3 pnLightProject(mat4 lightView, mat4 lightProjection, float mapSize, vec3 world) {
  vec4 view = lightView * vec4(world, 1.0);
  vec4 clip = lightProjection * view;
  return vec3((clip.xy / clip.w * 0.5 + 0.5) * mapSize, -view.z);
}

#endif  // PENUMBRA_LIGHT_MODEL_GLSL
