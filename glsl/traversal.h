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

// How an ambiguous leaf is estimated: the sample table's §3.2 samples, or
// HQEPCSS's "every texel occludes at the node's min".
#define PN_LEAF_SAMPLED 0
#define PN_LEAF_MIN 1

#endif  // PENUMBRA_TRAVERSAL_H
