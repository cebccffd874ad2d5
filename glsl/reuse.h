// reuse.h — the constants that glsl/reuse.glsl and the C++ runner share: the
// parent codes (stored as floats in the parents image, read back by
// runner/check/reuse_check.cpp and the pipeline) and the largest tile
// (runner/reference/reuse_reference.h kReuseMaxTile). Valid as GLSL and as
// C++: only comments and guarded #defines. An engine may define
// PN_REUSE_MAX_TILE before including reuse.glsl.

#ifndef PENUMBRA_REUSE_H
#define PENUMBRA_REUSE_H

// Largest tile side k (loop bound of pnReuseRepresentative).
#ifndef PN_REUSE_MAX_TILE
#define PN_REUSE_MAX_TILE 16
#endif

// pnReuseParent's codes: a representative, linked to the left neighbour, linked to the top one.
#define PN_REUSE_NONE 0
#define PN_REUSE_LEFT 1
#define PN_REUSE_TOP 2

#endif  // PENUMBRA_REUSE_H
