// light_model.glsl — the light and its widths in shadow-map texels: a square
// area light with a perspective shadow map, or a directional light (the sun)
// with an angular size and an orthographic shadow map (a cascade).
//
// description:
//   SPEC §4.7: a square area light of world width w_L at the shadow map's
//   viewpoint, facing along its axis; the shadow map is a perspective view
//   from the light's centre with near plane n, far plane f and a near-plane
//   world width W_n = 2 n tan(fov / 2), N×N texels, storing linear depth
//   (distance along the axis). A texel's world width at depth d is
//   d W_n / (n N). By similar triangles:
//   - blockers at depth z that can shadow a receiver at depth dP lie in a
//     window of world width w_L (dP - z) / dP at depth z, which projects to
//       blockerWindowTexels(dP, z) = w_L (dP - z) / dP · (n / z) / W_n · N
//     (the blocker search: z = n for PCSS's initial search, z = zmin when
//     the pyramid has refined it — HQEPCSS);
//   - the penumbra of Eq. (1) is a world width at the receiver,
//       s_p = w_L (dP - dz) / dz   (dz: the blocker mean),
//     which projects to penumbraTexels = s_p · (n / dP) / W_n · N.
//   (NVIDIA's filterRadiusUV = penumbraRatio · lightSizeUV · near / zReceiver
//   is the second formula as a radius in UV.)
//   The directional light (seed 003's sun, issue 14) is the same light moved
//   to infinity with its angular width kept: a light of angular diameter θ
//   seen from any point has the width S = 2 tan(θ / 2) per unit of distance
//   (spread), and an orthographic map has one texel width t everywhere
//   (texelWorld), so
//       blocker window = S (dP - z) / t,   s_p = S (dP - dz),   penumbra = s_p / t
//   texels: the penumbra still grows with the blocker distance, linearly.
//   Both lights in one formula: window = (dP - z)(w_L / dP + S) / texel(z),
//   s_p = (dP - dz)(w_L / dz + S), penumbra = s_p / texel(dP), with
//   texel(d) = t when texelWorld = t > 0 and d W_n / (n N) otherwise; an area
//   light has S = 0 and t = 0, a directional light w_L = 0 and W_n unused.
//   Every technique takes its widths from here; runner/scene/light_model.h
//   is the same on the CPU.
//   Degenerate inputs give 0 texels (a hard shadow), never NaN: a zero light,
//   a receiver or blocker at or before the near plane (the orthographic
//   map's depth range start), a blocker at or behind the receiver, a zero
//   texel width, non-finite values.
//
// use:
//   PnLight { float width; float near; float nearPlaneWidth; float mapSize; float spread; float texelWorld; }
//   float pnLightTexelWorld(PnLight light, float depth)   a texel's world width at light depth `depth`
//   float pnLightBlockerWindowTexels(PnLight light, float receiverDepth, float blockerDepth)
//   float pnLightSearchWidthTexels(PnLight light, float receiverDepth)     = window for z = near
//   float pnLightPenumbraWorld(PnLight light, float receiverDepth, float blockerDepth)
//   float pnLightPenumbraTexels(PnLight light, float receiverDepth, float blockerDepth)
//   vec3  pnLightProject(mat4 lightView, mat4 lightProjection, float mapSize, vec3 world)
//         a world point in the shadow map's terms: (u, v) in texels (continuous, texel i
//         spans [i, i + 1)) and its linear light depth; depth <= 0: behind the light
//         (u, v then meaningless). What the G-buffer stores and a hard shadow looks up.
//         (Perspective or orthographic projection alike.)
//   float pnLightDepthFromDepthBuffer(mat4 lightProjection, float depth, bool zeroToOneClip)
//         the linear light depth (the distance along the axis the modules read) of a value of the
//         light's hardware depth buffer written through lightProjection: NDC z = depth when the clip
//         range is [0, 1] (Vulkan, D3D, glClipControl's GL_ZERO_TO_ONE), else 2 depth - 1 (OpenGL's
//         default), then NDC z = clip.z / clip.w solved for the view depth. Perspective or
//         orthographic, reversed-Z or not, finite or infinite far plane: any projection whose z and
//         w rows read only the view z. The cleared depth gives the far plane (no occluder nearer).
//         Precision: docs/integration.md ("From the hardware depth buffer").
//
// cost: a few ALU operations.

#ifndef PENUMBRA_LIGHT_MODEL_GLSL
#define PENUMBRA_LIGHT_MODEL_GLSL

struct PnLight {
  float width;           // w_L, world units (area light; 0 for a directional one)
  float near;            // n, world units along the axis (orthographic: the depth range's start)
  float nearPlaneWidth;  // W_n = 2 n tan(fov / 2) (perspective)
  float mapSize;         // N, texels
  float spread;          // S = 2 tan(theta / 2), the directional light's width per unit of distance (0: none)
  float texelWorld;      // t, an orthographic map's texel width in world units; 0: perspective
};

// x when finite and positive, else 0.
float pn_lightPositiveOrZero(float x) {
  return (x > 0.0 && !isinf(x)) ? x : 0.0;
}

// t for an orthographic map, d W_n / (n N) for a perspective one; 0 (no usable texel) for
// degenerate lights, so that the widths below come out 0.
float pnLightTexelWorld(PnLight light, float depth) {
  if (light.texelWorld > 0.0) return light.texelWorld;
  if (!(light.near > 0.0) || !(light.nearPlaneWidth > 0.0) || !(light.mapSize > 0.0)) return 0.0;
  return pn_lightPositiveOrZero(depth * light.nearPlaneWidth / (light.near * light.mapSize));
}

float pnLightBlockerWindowTexels(PnLight light, float receiverDepth, float blockerDepth) {
  if (!(receiverDepth > blockerDepth) || !(blockerDepth >= light.near) || !(light.near > 0.0)) return 0.0;
  float texel = pnLightTexelWorld(light, blockerDepth);
  if (!(texel > 0.0)) return 0.0;
  float world = (receiverDepth - blockerDepth) * (light.width / receiverDepth + light.spread);
  return pn_lightPositiveOrZero(world / texel);
}

float pnLightSearchWidthTexels(PnLight light, float receiverDepth) {
  return pnLightBlockerWindowTexels(light, receiverDepth, light.near);
}

float pnLightPenumbraWorld(PnLight light, float receiverDepth, float blockerDepth) {
  if (!(receiverDepth > blockerDepth) || !(blockerDepth > 0.0)) return 0.0;
  return pn_lightPositiveOrZero((receiverDepth - blockerDepth) * (light.width / blockerDepth + light.spread));
}

float pnLightPenumbraTexels(PnLight light, float receiverDepth, float blockerDepth) {
  if (!(receiverDepth >= light.near) || !(light.near > 0.0)) return 0.0;
  float texel = pnLightTexelWorld(light, receiverDepth);
  if (!(texel > 0.0)) return 0.0;
  return pn_lightPositiveOrZero(pnLightPenumbraWorld(light, receiverDepth, blockerDepth) / texel);
}

float pnLightDepthFromDepthBuffer(mat4 lightProjection, float depth, bool zeroToOneClip) {
  float ndcZ = zeroToOneClip ? depth : 2.0 * depth - 1.0;
  // clip.z = a v + b, clip.w = c v + d for the view z v (column-major: m[column][row]); the light looks down -z.
  float a = lightProjection[2][2], b = lightProjection[3][2], c = lightProjection[2][3], d = lightProjection[3][3];
  return (b - ndcZ * d) / (a - ndcZ * c);
}

vec3 pnLightProject(mat4 lightView, mat4 lightProjection, float mapSize, vec3 world) {
  vec4 view = lightView * vec4(world, 1.0);
  vec4 clip = lightProjection * view;
  return vec3((clip.xy / clip.w * 0.5 + 0.5) * mapSize, -view.z);
}

#endif  // PENUMBRA_LIGHT_MODEL_GLSL
