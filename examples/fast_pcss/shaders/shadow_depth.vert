// shadow_depth.vert — the shadow map: the light's clip position, and the
// linear light depth (distance along the light's axis) for the fragment stage.

layout(location = EX_POSITION_ATTRIBUTE) in vec3 inPosition;
layout(location = EX_LIGHT_VIEW_LOCATION) uniform mat4 uLightView;
layout(location = EX_LIGHT_PROJECTION_LOCATION) uniform mat4 uLightProjection;

out float vLightDepth;

void main() {
  vec4 view = uLightView * vec4(inPosition, 1.0);
  vLightDepth = -view.z;  // the light looks down its view's -z
  gl_Position = uLightProjection * view;
}
