// backprojection_shade.comp — backprojection_shade.glsl's visibility in a compute pass, one
// invocation a pixel (the runner's default stage; shade_pass.h).

layout(local_size_x = 8, local_size_y = 8) in;

#include "backprojection_shade.glsl"

layout(r32f, binding = PN_BACKPROJECTION_SHADE_VISIBILITY_IMAGE) writeonly uniform image2D pnVisibility;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnVisibility)))) return;
  imageStore(pnVisibility, p, vec4(pnShade(p), 0.0, 0.0, 0.0));
}
