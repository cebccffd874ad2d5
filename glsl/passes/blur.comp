// blur.comp — one 1-D pass of blur.glsl over a whole R32F image.
// The runner dispatches it twice: axis (1,0) into a temporary, then axis
// (0,1) into the target. Bindings and the parameter block: blur.h. With the
// adaptive radius each pixel takes its radius from the filter map (a pixel
// of radius 0 is a copy of its texel: pnBlur1DAdaptive).
//
// options:
//   PN_BLUR_PASS_DEPTH_AWARE, PN_BLUR_PASS_ADAPTIVE   the variant, true or
//   false; the runner compiles one program per variant (the driver drops the
//   other paths; llvmpipe runs every side of a non-constant branch: 78 ms
//   instead of 42 for the fixed radius at 1024²). Undefined, as
//   lint and bundle see the pass, they follow the parameter block.

layout(local_size_x = 8, local_size_y = 8) in;

#include "blur.h"

layout(binding = PN_BLUR_SOURCE_BINDING) uniform sampler2D pnBlurSource;
layout(binding = PN_BLUR_DEPTH_BINDING) uniform sampler2D pnBlurDepth;
layout(binding = PN_BLUR_FILTER_MAP_BINDING) uniform sampler2D pnBlurFilterMap;
layout(r32f, binding = PN_BLUR_TARGET_BINDING) writeonly uniform image2D pnBlurTarget;

#include "blur.glsl"

#ifndef PN_BLUR_PASS_DEPTH_AWARE
#define PN_BLUR_PASS_DEPTH_AWARE (pnParams.depthAware != 0)
#endif
#ifndef PN_BLUR_PASS_ADAPTIVE
#define PN_BLUR_PASS_ADAPTIVE (pnParams.adaptive != 0)
#endif

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnBlurTarget)))) return;
  float v;
  if (PN_BLUR_PASS_ADAPTIVE) {
    if (PN_BLUR_PASS_DEPTH_AWARE)
      v = pnBlur1DDepthAwareAdaptive(pnBlurSource, pnBlurDepth, pnBlurFilterMap, p, pnParams.axis, pnParams.radius,
                                     pnParams.sigma, pnParams.depthTolerance, pnParams.pixelsPerTexel);
    else
      v = pnBlur1DAdaptive(pnBlurSource, pnBlurFilterMap, p, pnParams.axis, pnParams.radius, pnParams.sigma,
                           pnParams.pixelsPerTexel);
  } else if (PN_BLUR_PASS_DEPTH_AWARE) {
    v = pnBlur1DDepthAware(pnBlurSource, pnBlurDepth, p, pnParams.axis, pnParams.radius, pnParams.sigma,
                           pnParams.depthTolerance);
  } else {
    v = pnBlur1D(pnBlurSource, p, pnParams.axis, pnParams.radius, pnParams.sigma);
  }
  imageStore(pnBlurTarget, p, vec4(v, 0.0, 0.0, 0.0));
}
