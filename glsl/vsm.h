// vsm.h — the constants that glsl/vsm.glsl and the C++ runner share: the
// default minimum variance and light-bleeding reduction, EVSM's default
// exponents and their fp32 bound, the moment kinds, the depth-range bound's codes
// (runner/reference/vsm_reference.h takes its values from these macros).
// Valid as GLSL and as C++: only comments and guarded #defines. An engine may
// define them before including vsm.glsl.

#ifndef PENUMBRA_VSM_H
#define PENUMBRA_VSM_H

// Minimum variance, relative to the squared mean: sigma^2 >= PN_VSM_MIN_VARIANCE * mu^2
// (scaled by the depth, so it means the same at every depth and in EVSM's warped units;
// it must exceed float cancellation in E[d^2] - E[d]^2, about 2^-23 relative).
#ifndef PN_VSM_MIN_VARIANCE
#define PN_VSM_MIN_VARIANCE 1.0e-4
#endif

// The variance's absolute floor: FLT_MIN (2^-126), so that the bound never divides 0 by 0
// (a mean of 0 makes the relative floor 0) and stays the same when denormals are flushed.
#define PN_VSM_VARIANCE_FLOOR 1.17549435e-38

// Light-bleeding reduction: p -> linstep(amount, 1, p); 0 leaves p unchanged.
#ifndef PN_VSM_BLEEDING_REDUCTION
#define PN_VSM_BLEEDING_REDUCTION 0.2
#endif
// The amount is clamped to [0, PN_VSM_MAX_BLEEDING_REDUCTION] (1 would divide by zero).
#ifndef PN_VSM_MAX_BLEEDING_REDUCTION
#define PN_VSM_MAX_BLEEDING_REDUCTION 0.99
#endif

// EVSM exponents (positive c+, negative c-), on depth normalised to x in [0, 1].
// fp32 bound: the second moment exp(2 c x) and the Chebyshev denominator
// sigma^2 + (t - mu)^2 <= 2 exp(2 c) must stay below FLT_MAX = 3.4e38 = exp(88.72):
// 2 c + ln 2 < 88.72, so c < 44.0; PN_EVSM_MAX_EXPONENT = 42 leaves a margin of e^4.
// Exponents are clamped to [0, PN_EVSM_MAX_EXPONENT].
#ifndef PN_EVSM_POSITIVE_EXPONENT
#define PN_EVSM_POSITIVE_EXPONENT 40.0
#endif
#ifndef PN_EVSM_NEGATIVE_EXPONENT
#define PN_EVSM_NEGATIVE_EXPONENT 5.0
#endif
#ifndef PN_EVSM_MAX_EXPONENT
#define PN_EVSM_MAX_EXPONENT 42.0
#endif

// The moment kinds: VSM (d, d^2), EVSM with 2 components (w+, w+^2), with 4 (w+, w+^2, w-, w-^2).
#define PN_VSM_KIND_VSM 0
#define PN_VSM_KIND_EVSM2 1
#define PN_VSM_KIND_EVSM4 2

// What the depth-range bound decides (pnVsmDepthRangeBound).
#define PN_VSM_BOUND_NONE (-1.0)     // min < t <= max: the Chebyshev bound decides
#define PN_VSM_BOUND_LIT 1.0         // t <= window min: no texel occludes
#define PN_VSM_BOUND_SHADOWED 0.0    // t > window max: every texel occludes

#endif  // PENUMBRA_VSM_H
