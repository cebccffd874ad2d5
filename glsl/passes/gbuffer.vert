// gbuffer.vert — Step 2's vertex stage: world position to the camera's clip
// space; the world position goes on to the fragment stage.
//   location 0: world position        binding 0: PnGBufferParams (std140)

layout(location = 0) in vec3 pnPosition;
layout(location = 0) out vec3 pnWorld;

layout(std140, binding = 0) uniform PnGBufferParams {
  mat4 cameraViewProjection;
  mat4 lightView;
  mat4 lightProjection;
  vec4 cameraPosition;
  float mapSize;
  float normalOffset;
  float texelPerDepth;
} pnParams;

void main() {
  pnWorld = pnPosition;
  gl_Position = pnParams.cameraViewProjection * vec4(pnPosition, 1.0);
}
