// backprojection.h — what backprojection.glsl, backprojection_mask.glsl and the runner share: the light
// samples' layout and the option ranges. Valid as GLSL and as C++ (only
// guarded #defines), so the CPU reference places the same samples
// (runner/reference/backprojection_reference.cpp).

#ifndef PENUMBRA_BACKPROJECTION_H
#define PENUMBRA_BACKPROJECTION_H

// Light samples: side × side strata over the light's square, side a power of two (4, 8 or 16:
// 16, 64 or 256 samples), one sample a stratum, multi-jittered (Chiu, Shirley & Wang 1994) in
// its canonical order: sample k = i · side + j lies in stratum (column i, row j), in fine column
// k and fine row j · side + i of the side² × side² grid, so each fine column and each fine row
// holds one sample. Bit k of the coverage bitmask (up to 256 bits) is sample k: the samples in a
// range of fine columns are a range of bits, those in a range of fine rows its transpose — a
// box's samples are a few word operations, not a loop over the samples.
#define PN_BACKPROJECTION_MIN_SIDE 4
#define PN_BACKPROJECTION_MAX_SIDE 16
#define PN_BACKPROJECTION_DEFAULT_SIDE 16
#define PN_BACKPROJECTION_MASK_WORDS 8  // (PN_BACKPROJECTION_MAX_SIDE)² / 32

// Sample k's jitter inside its fine cell, as two 16-bit fractions from one 32-bit hash (a PCG
// step and an xorshift-multiply): fine index + jitter then needs at most 8 + 16 bits, and scaling
// by 1 / side² (a power of two) keeps it exact, so GLSL and C++ place every sample on the same
// float. Operands are 32-bit unsigned: uint in GLSL, std::uint32_t in C++.
#define PN_BACKPROJECTION_HASH_A(k) ((k) * 747796405u + 2891336453u)
#define PN_BACKPROJECTION_HASH_B(h) ((((h) >> (((h) >> 28u) + 4u)) ^ (h)) * 277803737u)
#define PN_BACKPROJECTION_HASH_C(h) ((h) ^ ((h) >> 22u))
#define PN_BACKPROJECTION_HASH(k) PN_BACKPROJECTION_HASH_C(PN_BACKPROJECTION_HASH_B(PN_BACKPROJECTION_HASH_A(k)))
#define PN_BACKPROJECTION_JITTER_BITS 16

// A node whose depth range is at most this share of its distance to the receiver (dP - min)
// stands as one patch: the default.
#define PN_BACKPROJECTION_DEFAULT_TOLERANCE 0.05

// Over slabs (the call with a second layer), a node stands as one slab when its first layer's range
// is within the tolerance and its second layer's within this many times it: the bottoms' depths
// decide only the rays that pass under a blocker's top, and resolving every texel of a blocker whose
// back varies (a tall box's sides, seen from the light) visits every texel of its top for no
// measured gain in quality (docs/modules/backprojection.md).
#define PN_BACKPROJECTION_SECOND_LAYER_TOLERANCE 4.0

// Neighbouring texels whose depths differ by at most this many texel widths (at the nearer one's
// depth) are one surface, joined by a wall; a larger step is a silhouette, left open.
#define PN_BACKPROJECTION_DEFAULT_GAP 3.0

// A silhouette (a larger step) is closed by a wall from the shallower texel's depth d down to
// thickness · (dP - d), dP the receiver's depth (or to the deeper neighbour, if nearer): the
// occluder's assumed thickness as a share of its distance to the receiver. 0: silhouettes open
// (the surface alone); 1: the height field (every texel solid down to the receiver).
#define PN_BACKPROJECTION_DEFAULT_THICKNESS 0.1

// Mesa's llvmpipe and lavapipe count every loop iteration of a shader invocation (all loops, a
// SIMD group of invocations together) against one limit of 65535 and silently leave every loop
// once it is spent. The traversal counts its own iterations (a node 1, a wall its mask words and
// the samples it tests; a patch has no loop) and stops resolving nodes past this many: the nodes
// left stand as patches, estimated rather than cut off.
#define PN_BACKPROJECTION_MAX_WORK 32768

// Default node budget (nodes of the mip chain visited a receiver) and the largest one.
#define PN_BACKPROJECTION_DEFAULT_BUDGET 4096
#define PN_BACKPROJECTION_MAX_BUDGET 60000  // the traversal loop's bound; PN_BACKPROJECTION_MAX_WORK
                                             // ends resolving sooner on a receiver that heavy

#endif  // PENUMBRA_BACKPROJECTION_H
