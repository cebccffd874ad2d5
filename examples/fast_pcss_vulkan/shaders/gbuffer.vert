#version 450
// gbuffer.vert — the camera's clip position; the world position goes on to gbuffer.frag.
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
layout(location = 0) in vec3 inPosition;
layout(location = 0) out vec3 vWorld;
void main() {
  vWorld = inPosition;
  gl_Position = exCameraRaster * vec4(inPosition, 1.0);
}
