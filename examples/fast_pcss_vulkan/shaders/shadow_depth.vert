#version 450
// shadow_depth.vert — the shadow map: the light's clip position, and the linear light depth
// (the distance along the light's axis) for the fragment stage.
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
layout(location = 0) in vec3 inPosition;
layout(location = 0) out float vLightDepth;
void main() {
  vec4 view = exLightView * vec4(inPosition, 1.0);
  vLightDepth = -view.z;  // the light looks down its view's -z
  gl_Position = exLightRaster * view;
}
