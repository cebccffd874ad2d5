// hard_shadow.vert — the physical reference's camera pass, vertex stage: world
// position to the camera's clip space; the world position goes on to the
// fragment stage, which tests it against one point light's shadow map.
//   location 0: world position        binding 0: PnHardShadowParams (std140)

layout(location = 0) in vec3 pnPosition;
layout(location = 0) out vec3 pnWorld;

layout(std140, binding = 0) uniform PnHardShadowParams {
  mat4 cameraViewProjection;
  mat4 lightView;        // the sample point's view: same orientation as the area light's centre
  mat4 lightProjection;
  float mapSize;         // N
  float bias;            // linear depth units
  float divisor;         // of the running count: 1, or the number of samples on the last pass
} pnParams;

void main() {
  pnWorld = pnPosition;
  gl_Position = pnParams.cameraViewProjection * vec4(pnPosition, 1.0);
}
