// backprojection.h — what backprojection.glsl and the runner share: the light
// samples' layout and the option ranges. Valid as GLSL and as C++ (only
// guarded #defines), so the CPU reference places the same samples
// (runner/reference/backprojection_reference.cpp).

#ifndef PENUMBRA_BACKPROJECTION_H
#define PENUMBRA_BACKPROJECTION_H

// Light samples: side × side strata over the light's square, side a power of two (4, 8 or 16:
// 16, 64 or 256 samples), one sample a stratum; the coverage bitmask holds up to 256 bits.
#define PN_BACKPROJECTION_MIN_SIDE 4
#define PN_BACKPROJECTION_MAX_SIDE 16
#define PN_BACKPROJECTION_DEFAULT_SIDE 8
#define PN_BACKPROJECTION_MASK_WORDS 8  // (PN_BACKPROJECTION_MAX_SIDE)² / 32

// Sample k's jitter inside its stratum, as two 19-bit fractions from one 32-bit hash (a PCG
// step and an xorshift-multiply): stratum x + jitter then needs at most 4 + 19 bits, and scaling
// by 1 / side (a power of two) keeps it exact, so GLSL and C++ place every sample on the same
// float. Operands are 32-bit unsigned: uint in GLSL, std::uint32_t in C++.
#define PN_BACKPROJECTION_HASH_A(k) ((k) * 747796405u + 2891336453u)
#define PN_BACKPROJECTION_HASH_B(h) ((((h) >> (((h) >> 28u) + 4u)) ^ (h)) * 277803737u)
#define PN_BACKPROJECTION_HASH_C(h) ((h) ^ ((h) >> 22u))
#define PN_BACKPROJECTION_HASH(k) PN_BACKPROJECTION_HASH_C(PN_BACKPROJECTION_HASH_B(PN_BACKPROJECTION_HASH_A(k)))
#define PN_BACKPROJECTION_JITTER_BITS 19

// A node whose depth range is at most this share of its distance to the receiver (dP - min)
// stands as one patch: the default.
#define PN_BACKPROJECTION_DEFAULT_TOLERANCE 0.05

// Neighbouring texels whose depths differ by at most this many texel widths (at the nearer one's
// depth) are one surface, joined by a wall; a larger step is a silhouette, left open.
#define PN_BACKPROJECTION_DEFAULT_GAP 3.0

// Default node budget (nodes of the mip chain visited a receiver) and the largest one.
#define PN_BACKPROJECTION_DEFAULT_BUDGET 4096
#define PN_BACKPROJECTION_MAX_BUDGET 60000  // under llvmpipe's 65535 iterations a loop

#endif  // PENUMBRA_BACKPROJECTION_H
