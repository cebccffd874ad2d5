// gbuffer.frag — Step 2: for the surface point seen through the pixel, its
// shadow-map position in texels (continuous: texel i spans [i, i + 1)) and its
// linear light depth; w = 1 marks a pixel that sees a surface (cleared to 0).
// Normal offset (Holbert 2011): the point is first moved off its face, along
// the face normal (towards the camera), by normalOffset shadow-map texels at
// its light depth, so that faces seen edge-on by the light (box walls) do not
// shadow themselves in stripes; 0 keeps the surface point itself.

#include "light_model.glsl"

layout(location = 0) in vec3 pnWorld;
layout(location = 0) out vec4 pnReceiver;

layout(std140, binding = 0) uniform PnGBufferParams {
  mat4 cameraViewProjection;
  mat4 lightView;
  mat4 lightProjection;
  vec4 cameraPosition;  // xyz
  float mapSize;
  float normalOffset;   // texels
  float texelPerDepth;  // a texel's world width per unit of light depth: W_n / (n N)
} pnParams;

void main() {
  vec3 world = pnWorld;
  if (pnParams.normalOffset > 0.0) {
    vec3 n = normalize(cross(dFdx(pnWorld), dFdy(pnWorld)));
    if (dot(n, pnParams.cameraPosition.xyz - pnWorld) < 0.0) n = -n;
    float depth = -(pnParams.lightView * vec4(pnWorld, 1.0)).z;
    world += n * (pnParams.normalOffset * pnParams.texelPerDepth * depth);
  }
  pnReceiver = vec4(pnLightProject(pnParams.lightView, pnParams.lightProjection, pnParams.mapSize, world), 1.0);
}
