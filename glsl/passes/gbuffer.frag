// gbuffer.frag — Step 2: for the surface point seen through the pixel, its
// shadow-map position in texels (continuous: texel i spans [i, i + 1)) and its
// linear light depth; w = 1 marks a pixel that sees a surface (cleared to 0).

layout(location = 0) in vec3 pnWorld;
layout(location = 0) out vec4 pnReceiver;

layout(std140, binding = 0) uniform PnGBufferParams {
  mat4 cameraViewProjection;
  mat4 lightView;
  mat4 lightProjection;
  float mapSize;
} pnParams;

void main() {
  vec4 view = pnParams.lightView * vec4(pnWorld, 1.0);
  vec4 clip = pnParams.lightProjection * view;
  vec2 texel = (clip.xy / clip.w * 0.5 + 0.5) * pnParams.mapSize;
  pnReceiver = vec4(texel, -view.z, 1.0);
}
