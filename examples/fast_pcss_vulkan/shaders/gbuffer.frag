#version 450
// gbuffer.frag — what the shading pass needs of each pixel: its receiver in the shadow map's terms
// (pnLightProject, from the bundle of fast_pcss.glsl), its world position and albedo, its normal.
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
#include "fast_pcss_bundle.glsl"  // generated: penumbra_bundle(... MODULE fast_pcss.glsl BARE)
#include "light.glsl"
layout(push_constant) uniform ExDraw { int albedo; } draw;  // 0 ground, 1 model
layout(location = 0) in vec3 vWorld;
layout(location = 0) out vec4 outReceiver;
layout(location = 1) out vec4 outWorld;
layout(location = 2) out vec4 outNormal;
void main() {
  // The face normal from the screen-space derivatives (no normal attribute), turned toward the camera.
  vec3 normal = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
  if (dot(normal, exCameraPosition.xyz - vWorld) < 0.0) normal = -normal;
  // The receiver: (u, v) in texels and linear light depth, of the point moved exLight1.w shadow-map
  // texels off its face.
  PnLight light = exPnLight();
  float lightDepth = -(exLightView * vec4(vWorld, 1.0)).z;
  vec3 offsetWorld = vWorld + normal * (exLight1.w * pnLightTexelWorld(light, lightDepth));
  outReceiver = vec4(pnLightProject(exLightView, exLightProjection, light.mapSize, offsetWorld), 1.0);
  outWorld = vec4(vWorld, float(draw.albedo));
  outNormal = vec4(normal, 0.0);
}
