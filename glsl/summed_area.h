// summed_area.h — the constants that glsl/summed_area.glsl and the C++ runner
// share: the fixed-point step, the magnitude clamp, the loop bound and the
// two build directions (runner/reference/summed_area_reference.h,
// runner/pass_runners/summed_area_pass.cpp). Valid as GLSL and as C++: only
// comments and guarded #defines. An engine may define the options before
// including summed_area.glsl.

#ifndef PENUMBRA_SUMMED_AREA_H
#define PENUMBRA_SUMMED_AREA_H

// Fixed-point step 2^-F of the table's values: a depth d counts as the integer
// q = roundEven(d * 2^F). 0 <= F <= PN_SUMMED_AREA_MAGNITUDE_BITS. With 20, a
// float depth of magnitude >= 2^(23 - 20) = 8 is a multiple of the step
// (quantised exactly); smaller ones are off by at most 2^-21 (4.8e-7).
#ifndef PN_SUMMED_AREA_FRACTION_BITS
#define PN_SUMMED_AREA_FRACTION_BITS 20
#endif

// |q| <= 2^52: finite depths beyond 2^(52 - F) in magnitude (4.3e9 at F = 20)
// are clamped to it, so every texel's q is defined and fits in 64 bits.
#define PN_SUMMED_AREA_MAGNITUDE_BITS 52

// Loop bound: maps up to PN_SUMMED_AREA_MAX_SIDE texels a side (the table has
// one more row and column). Below llvmpipe's 65535 loop iterations per invocation.
#ifndef PN_SUMMED_AREA_MAX_SIDE
#define PN_SUMMED_AREA_MAX_SIDE 16384
#endif

// The two build passes: prefix sums along each row of the map, then down each
// column of the row-prefix table.
#define PN_SUMMED_AREA_ROWS 0
#define PN_SUMMED_AREA_COLUMNS 1

// Moments tables (seed 004's summed-area variance shadow maps): the first two
// moments of the depth mapped to the unit range, x = (d - offset) * scale
// clamped to [0, 1] (offset = the light's near plane, scale = 1 / (far - near);
// non-finite depths: x = 1, the far plane).
// Fixed point: q = roundEven(x * 2^B), B = PN_SUMMED_AREA_MOMENT_BITS; the
// table holds (sum of q, sum of q^2), each modulo 2^64. With B <= 18 every
// rectangle of every table the module builds (up to 16384^2 = 2^28 texels)
// keeps its centred second moment sum (q - c)^2 (c the rounded mean of q)
// below 2^28 (2^34 + 3) < 2^63: the variance comes out exact before its one
// conversion to float. Depth step: (far - near) * 2^-B.
#ifndef PN_SUMMED_AREA_MOMENT_BITS
#define PN_SUMMED_AREA_MOMENT_BITS 18
#endif
#define PN_SUMMED_AREA_MAX_MOMENT_BITS 18

// What a table holds (the build pass's PN_SUMMED_AREA_BUILD_KIND):
#define PN_SUMMED_AREA_KIND_DEPTH 0          // RGBA32UI (sum of q(d) low, high, finite count, 0): the traversal's
#define PN_SUMMED_AREA_KIND_MOMENTS 1        // RGBA32UI (sum of q low, high, sum of q^2 low, high): fixed point
#define PN_SUMMED_AREA_KIND_FLOAT_MOMENTS 2  // RG32F (RGBA32F on ES) (sum of x - 1/2, sum of (x - 1/2)^2): float

#endif  // PENUMBRA_SUMMED_AREA_H
