// shadow_depth.vert — the shadow map's vertex stage: world position to clip
// space of the light, and the linear light depth (distance along the light's
// axis, SPEC §3) for the fragment stage.
//   location 0: world position        binding 0: PnShadowDepthParams (std140)

layout(location = 0) in vec3 pnPosition;
layout(location = 0) out float pnLinearDepth;

layout(std140, binding = 0) uniform PnShadowDepthParams {
  mat4 lightView;
  mat4 lightProjection;
} pnParams;

void main() {
  vec4 view = pnParams.lightView * vec4(pnPosition, 1.0);
  pnLinearDepth = -view.z;
  gl_Position = pnParams.lightProjection * view;
}
