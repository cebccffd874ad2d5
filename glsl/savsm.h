// savsm.h — the constants that glsl/savsm.glsl and the C++ runner share: the
// table kinds, the blocker-search modes, the default filter scale and the
// fetch counts of one receiver (runner/reference/savsm_reference.h takes its
// values from these macros). Valid as GLSL and as C++: only comments and
// guarded #defines. An engine may define the options before including savsm.glsl.

#ifndef PENUMBRA_SAVSM_H
#define PENUMBRA_SAVSM_H

// Which moments table the module reads (summed_area.glsl): 64-bit fixed point
// (exact box sums, a usampler2D) or centred float (a sampler2D). One per
// program: the table's sampler type follows it.
#define PN_SAVSM_TABLE_FIXED 0
#define PN_SAVSM_TABLE_FLOAT 1
#ifndef PN_SAVSM_TABLE
#define PN_SAVSM_TABLE PN_SAVSM_TABLE_FIXED
#endif

// The blocker search over PCSS's search square:
//   TABLE: the average blocker depth from the square's mean and variance by
//     Chebyshev's bound (Lauritzen's SAVSM / Yang et al.'s VSSM): the
//     unoccluded share p is at depth t, so z = (mu - p t) / (1 - p);
//   MIN: the square's minimum depth from the min/max mip chain (the nearest
//     blocker: the widest penumbra the square allows).
#define PN_SAVSM_BLOCKER_TABLE 0
#define PN_SAVSM_BLOCKER_MIN 1

// pnSavsmDefaults' blocker mode and bound (1 on, 0 off): MIN with the bound is
// nearer the ray-traced truth than the seed's TABLE (docs/modules/savsm.md).
#define PN_SAVSM_DEFAULT_BLOCKER PN_SAVSM_BLOCKER_MIN
#define PN_SAVSM_DEFAULT_BOUND 1

// c: filter side = c · penumbra (as the PCSS family's filter scale).
#ifndef PN_SAVSM_FILTER_SCALE
#define PN_SAVSM_FILTER_SCALE 1.0
#endif

// The TABLE estimate reads a search square whose Chebyshev bound leaves an
// occluded share 1 - p below this as lit: no blocker (its depth would rest on
// a vanishing share of the square).
#define PN_SAVSM_MIN_OCCLUDED 1.0e-4

// Texel fetches of one receiver, whatever its widths: a moments rectangle is
// 4 table fetches, a square's min/max at most 9 mip-chain fetches (the
// aligned nodes covering it, minmax_mip.glsl). At most 4 + 9 for the search
// and 4 + 9 for the filter.
#define PN_SAVSM_RECT_FETCHES 4
#define PN_SAVSM_MAX_SQUARE_FETCHES 9

#endif  // PENUMBRA_SAVSM_H
