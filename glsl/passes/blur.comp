// blur.comp — one 1-D pass of blur.glsl over a whole R32F image.
// The runner dispatches it twice: axis (1,0) into a temporary, then axis
// (0,1) into the target. Bindings and the parameter block: blur.h.

layout(local_size_x = 8, local_size_y = 8) in;

#include "blur.h"

layout(binding = PN_BLUR_SOURCE_BINDING) uniform sampler2D pnBlurSource;
layout(binding = PN_BLUR_DEPTH_BINDING) uniform sampler2D pnBlurDepth;
layout(r32f, binding = PN_BLUR_TARGET_BINDING) writeonly uniform image2D pnBlurTarget;

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
