// fast_pcss.h — Fast PCSS's shipped defaults (fast_pcss.glsl's
// pnFastPcssDefaults), shared with the runner (runner/modules/fast_pcss_face.h:
// the `fast` technique's settings are these). Valid as GLSL and as C++:
// only comments and guarded #defines.

#ifndef PENUMBRA_FAST_PCSS_H
#define PENUMBRA_FAST_PCSS_H

#include "traversal.h"  // PN_TRAVERSAL_NO_BUDGET

// Step 3: refinements of the search region from the mip chain (0: PCSS's search width).
#define PN_FAST_PCSS_REFINE_ITERATIONS 3
// Traversal leaves of this side or smaller are estimated from the sample table (1: exact counts).
#define PN_FAST_PCSS_LEAF_SIDE 16
// The work budget (issue 52, docs/modules/fast_pcss.md "The work budget"), two settings:
// - leafDivisor: a region is walked to leaves of at least its longer side / this, rounded down to a
//   power of two, so at most 2 x this many leaves lie along a side whatever the light's width (0: no
//   bound, leaves of PN_FAST_PCSS_LEAF_SIDE at every width);
// - leafMode: an ambiguous leaf is estimated from the sample table's 4-sample group whatever its
//   side (PN_LEAF_QUAD), not from 16 samples for sides 8 and above (PN_LEAF_SAMPLED, the paper's).
// leafDivisor 0 with PN_LEAF_SAMPLED is the unbounded walk the budget is measured against. An engine
// may define either before the include to change pnFastPcssDefaults' budget (the runner does, for
// `fast:leaf-divisor=D:leaf-mode=M`: the call as an engine would compile it).
#ifndef PN_FAST_PCSS_LEAF_DIVISOR
#define PN_FAST_PCSS_LEAF_DIVISOR 12
#endif
#ifndef PN_FAST_PCSS_LEAF_MODE
#define PN_FAST_PCSS_LEAF_MODE PN_LEAF_QUAD
#endif
// Nodes a traversal may visit before it stops descending: no bound.
#define PN_FAST_PCSS_NODE_BUDGET PN_TRAVERSAL_NO_BUDGET
// Steps 4 and 5 traverse (0), or count over a grid of this many cells a side (pnGridRegionMip).
#define PN_FAST_PCSS_GRID 0
// blockerLeafMode's "as leafMode".
#define PN_FAST_PCSS_SAME_LEAF_MODE -1

#endif  // PENUMBRA_FAST_PCSS_H
