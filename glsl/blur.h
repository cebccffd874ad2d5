// blur.h — the constants that glsl/blur.glsl and the C++ runner share: the
// default radius and sigma (runner/reference/blur_reference.h BlurParams),
// the radius bound and the value of non-finite texels (kBlurMaxRadius,
// kBlurNonfiniteValue, which the CPU reference uses). Valid as GLSL and as
// C++: only comments and guarded #defines. An engine may define them before
// including blur.glsl.

#ifndef PENUMBRA_BLUR_H
#define PENUMBRA_BLUR_H

// Default radius and sigma for callers (seed 000 §5.3: radius 3; 3 sigma = radius).
#ifndef PN_BLUR_RADIUS
#define PN_BLUR_RADIUS 3
#endif
#ifndef PN_BLUR_SIGMA
#define PN_BLUR_SIGMA 1.0
#endif

// Loop bound: radii are clamped to [0, PN_BLUR_MAX_RADIUS].
#ifndef PN_BLUR_MAX_RADIUS
#define PN_BLUR_MAX_RADIUS 16
#endif

// Value substituted for NaN and ±Inf texels.
#ifndef PN_BLUR_NONFINITE_VALUE
#define PN_BLUR_NONFINITE_VALUE 0.0
#endif

#endif  // PENUMBRA_BLUR_H
