// summed_area.h — the constants that glsl/summed_area.glsl and the C++ runner
// share: the fixed-point step, the magnitude clamp, the loop bound and the
// two build directions (runner/reference/summed_area_reference.h,
// runner/passes/summed_area_pass.cpp). Valid as GLSL and as C++: only
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

#endif  // PENUMBRA_SUMMED_AREA_H
