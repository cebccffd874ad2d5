// minmax_mip.h — the level the aligned min/max chain starts at (minmax_mip.glsl), shared with the
// runner (runner/pass_runners/minmax_mip_pass.cpp: the chain's size and build). Valid as GLSL and as
// C++: only comments and guarded #defines.

#ifndef PENUMBRA_MINMAX_MIP_H
#define PENUMBRA_MINMAX_MIP_H

// Nodes of side 2^PN_MIP_FIRST_LEVEL and up are kept (4×4 texels): the levels below are the map
// itself, read where a texel's depth is needed. 16 · P² / 4^PN_MIP_FIRST_LEVEL · 4/3 / 2 bytes —
// 0.17× a 32-bit map.
#define PN_MIP_FIRST_LEVEL 2

#endif  // PENUMBRA_MINMAX_MIP_H
