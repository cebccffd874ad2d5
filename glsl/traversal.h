// traversal.h — the constants that glsl/traversal.glsl and the C++ runner
// share: the leaf modes (runner/reference/traversal_reference.h LeafMode)
// and the largest root level. Valid as GLSL and as C++: only comments and
// guarded #defines. An engine may define PN_TRAVERSAL_MAX_LEVEL before
// including traversal.glsl.

#ifndef PENUMBRA_TRAVERSAL_H
#define PENUMBRA_TRAVERSAL_H

// Largest root level: regions up to 2^13 = 8192 texels a side.
#ifndef PN_TRAVERSAL_MAX_LEVEL
#define PN_TRAVERSAL_MAX_LEVEL 13
#endif

// A node budget that never binds: 2^26 nodes a traversal.
#define PN_TRAVERSAL_NO_BUDGET 67108864

// How an ambiguous leaf is estimated: the sample table's §3.2 samples, or
// HQEPCSS's "every texel occludes at the node's min".
#define PN_LEAF_SAMPLED 0
#define PN_LEAF_MIN 1
// Or the ramp: the leaf's texels taken as spread evenly over [min, max] (a
// planar blocker's depths are): (t - min) / (max - min) of them occlude, at
// mean depth (min + t) / 2 — no fetch beyond the node's own.
#define PN_LEAF_RAMP 2
// Or the sample table's four-sample group (one sample a 2×2 stratum) for a leaf
// of any side >= 4 — PN_LEAF_SAMPLED's for sides 2 and 4, a quarter of its 16
// fetches for sides 8 and above (issue 52: Fast PCSS's shipped leaves).
#define PN_LEAF_QUAD 3

// Which structure a traversal reads: the paper's decreased pyramid (every
// window origin, depth_pyramid.glsl) or the aligned min/max mip chain with a
// summed-area table of depth (minmax_mip.glsl, summed_area.glsl).
#define PN_STRUCTURE_PYRAMID 0
#define PN_STRUCTURE_MIP 1

// The depth sums of the mip chain's wholly occluding nodes (pnTraverseRegionMip):
// none (counts only: Step 5), the summed-area table's exact sums, or each
// node's midpoint (min + max) / 2 times its texels (no table to build).
#define PN_DEPTH_SUMS_NONE 0
#define PN_DEPTH_SUMS_TABLE 1
#define PN_DEPTH_SUMS_MIDPOINT 2

// pnGridRegionMip's loop bound: cells per side of its grid (the grid has at most
// PN_GRID_MAX_CELLS + 1 aligned nodes a side, the region straddling them).
#define PN_GRID_MAX_CELLS 16

#endif  // PENUMBRA_TRAVERSAL_H
