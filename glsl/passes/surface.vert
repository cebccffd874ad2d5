// surface.vert — the surface pass's vertex stage: world position to the
// camera's clip space; the world position goes on to the fragment stage.
//   location 0: world position        binding 0: PnSurfaceParams (std140)

layout(location = 0) in vec3 pnPosition;
layout(location = 0) out vec3 pnWorld;

layout(std140, binding = 0) uniform PnSurfaceParams {
  mat4 cameraViewProjection;
  vec4 cameraPosition;  // xyz: world
  vec4 lightPosition;   // xyz: world, the area light's centre
  vec4 groundLo;        // xyz: the ground slab's box
  vec4 groundHi;
  vec4 groundAlbedo;    // rgb
  vec4 boxAlbedo;       // rgb
} pnParams;

void main() {
  pnWorld = pnPosition;
  gl_Position = pnParams.cameraViewProjection * vec4(pnPosition, 1.0);
}
