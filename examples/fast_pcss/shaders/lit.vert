// lit.vert — the camera's clip position; the world position goes on to lit.frag.

layout(location = EX_POSITION_ATTRIBUTE) in vec3 inPosition;
layout(location = EX_CAMERA_VIEW_PROJECTION_LOCATION) uniform mat4 uCameraViewProjection;

out vec3 vWorld;

void main() {
  vWorld = inPosition;
  gl_Position = uCameraViewProjection * vec4(inPosition, 1.0);
}
