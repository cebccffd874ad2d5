// blur.comp — one 1-D pass of blur.glsl over a whole R32F image.
// The runner dispatches it twice: axis (1,0) into a temporary, then axis
// (0,1) into the target. Bindings are distinct across resource kinds so the
// pass is valid Vulkan GLSL as well as GL 4.50 and ES 3.10.
//   binding 0: source (sampler2D, R32F)      binding 2: target (image2D, r32f)
//   binding 1: depth  (sampler2D, R32F)      binding 3: PnBlurPassParams (std140)

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D pnBlurSource;
layout(binding = 1) uniform sampler2D pnBlurDepth;
layout(r32f, binding = 2) writeonly uniform image2D pnBlurTarget;
layout(std140, binding = 3) uniform PnBlurPassParams {
  ivec2 axis;
  int radius;
  float sigma;
  int depthAware;  // 0: plain Gaussian, 1: depth-aware
  float depthTolerance;
} pnParams;

#include "blur.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnBlurTarget)))) return;
  float v = (pnParams.depthAware != 0)
      ? pnBlur1DDepthAware(pnBlurSource, pnBlurDepth, p, pnParams.axis, pnParams.radius, pnParams.sigma,
                           pnParams.depthTolerance)
      : pnBlur1D(pnBlurSource, p, pnParams.axis, pnParams.radius, pnParams.sigma);
  imageStore(pnBlurTarget, p, vec4(v, 0.0, 0.0, 0.0));
}
