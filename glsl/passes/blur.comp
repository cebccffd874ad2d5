// blur.comp — one 1-D pass of blur.glsl over a whole R32F, RG32F or RGBA32F image.
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
//   PN_BLUR_PASS_CHANNELS     1 (default), 2 or 4: the target's format
//   (r32f, rg32f, rgba32f; an image format is a compile-time qualifier;
//   ES 3.1 has no rg32f image format: 2 channels are stored as rgba32f there).
//   Every count runs the same code (blur.glsl's …Vec4 functions); one
//   channel stores their .r.

layout(local_size_x = 8, local_size_y = 8) in;

#include "blur_bindings.h"

layout(binding = PN_BLUR_SOURCE_BINDING) uniform sampler2D pnBlurSource;
layout(binding = PN_BLUR_DEPTH_BINDING) uniform sampler2D pnBlurDepth;
layout(binding = PN_BLUR_FILTER_MAP_BINDING) uniform sampler2D pnBlurFilterMap;
#ifndef PN_BLUR_PASS_CHANNELS
#define PN_BLUR_PASS_CHANNELS 1
#endif
#if PN_BLUR_PASS_CHANNELS == 4 || (PN_BLUR_PASS_CHANNELS == 2 && defined(GL_ES))
layout(rgba32f, binding = PN_BLUR_TARGET_BINDING) writeonly uniform image2D pnBlurTarget;
#elif PN_BLUR_PASS_CHANNELS == 2
layout(rg32f, binding = PN_BLUR_TARGET_BINDING) writeonly uniform image2D pnBlurTarget;
#else
layout(r32f, binding = PN_BLUR_TARGET_BINDING) writeonly uniform image2D pnBlurTarget;
#endif

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
#if PN_BLUR_PASS_CHANNELS == 1
  // One channel (a soft-shadow map; the blur check's images): the scalar calls an engine blurring
  // a visibility makes, so the checks run them (each is its …Vec4 form's .r).
  float s;
  if (PN_BLUR_PASS_ADAPTIVE) {
    if (PN_BLUR_PASS_DEPTH_AWARE)
      s = pnBlur1DDepthAwareAdaptive(pnBlurSource, pnBlurDepth, pnBlurFilterMap, p, pnParams.axis, pnParams.radius,
                                     pnParams.sigma, pnParams.depthTolerance, pnParams.pixelsPerTexel);
    else
      s = pnBlur1DAdaptive(pnBlurSource, pnBlurFilterMap, p, pnParams.axis, pnParams.radius, pnParams.sigma,
                           pnParams.pixelsPerTexel);
  } else if (PN_BLUR_PASS_DEPTH_AWARE) {
    s = pnBlur1DDepthAware(pnBlurSource, pnBlurDepth, p, pnParams.axis, pnParams.radius, pnParams.sigma,
                           pnParams.depthTolerance);
  } else {
    s = pnBlur1D(pnBlurSource, p, pnParams.axis, pnParams.radius, pnParams.sigma);
  }
  vec4 v = vec4(s, 0.0, 0.0, 0.0);
#else
  vec4 v;
  if (PN_BLUR_PASS_ADAPTIVE) {
    if (PN_BLUR_PASS_DEPTH_AWARE)
      v = pnBlur1DDepthAwareAdaptiveVec4(pnBlurSource, pnBlurDepth, pnBlurFilterMap, p, pnParams.axis,
                                         pnParams.radius, pnParams.sigma, pnParams.depthTolerance,
                                         pnParams.pixelsPerTexel);
    else
      v = pnBlur1DAdaptiveVec4(pnBlurSource, pnBlurFilterMap, p, pnParams.axis, pnParams.radius, pnParams.sigma,
                               pnParams.pixelsPerTexel);
  } else if (PN_BLUR_PASS_DEPTH_AWARE) {
    v = pnBlur1DDepthAwareVec4(pnBlurSource, pnBlurDepth, p, pnParams.axis, pnParams.radius, pnParams.sigma,
                               pnParams.depthTolerance);
  } else {
    v = pnBlur1DVec4(pnBlurSource, p, pnParams.axis, pnParams.radius, pnParams.sigma);
  }
#endif
#if PN_BLUR_PASS_CHANNELS == 4
  imageStore(pnBlurTarget, p, v);
#elif PN_BLUR_PASS_CHANNELS == 2
  imageStore(pnBlurTarget, p, vec4(v.rg, 0.0, 0.0));
#else
  imageStore(pnBlurTarget, p, vec4(v.r, 0.0, 0.0, 0.0));
#endif
}
