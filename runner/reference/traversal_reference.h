// CPU references for glsl/traversal.glsl.
// - brute_force_occluders: the definition — scan every texel of the region,
//   count those with d < t and sum their depths (double).
// - traversal_reference (decreased pyramid) and aligned_traversal_reference
//   (aligned mip chain): the same quadtree decisions made independently —
//   recursion instead of a stackless loop, node min/max/mean by scanning the
//   node's texels instead of the pyramid — with Eq. 5 / 6 at sampled leaves
//   computed directly from the same sample table. With leaf side 1 and an
//   unlimited budget it must equal brute force.
#pragma once

#include "core/image.h"
#include "core/texel_rect.h"
#include "sampling/sample_table.h"
#include "modules/traversal.h"

namespace pn {

// `depth` is a sanitized N×N map (sanitized_depths); `region` lies inside it.
TraversalResult brute_force_occluders(const Image& depth, const Rect& region, float receiver_depth, float bias);

// `max_level` is the pyramid's last level (nodes above it are not classified).
TraversalResult traversal_reference(const Image& depth, int max_level, const SampleTable& table, const Rect& region,
                                    const TraversalParams& params);

// The aligned mip chain's traversal (pnTraverseRegionMip), decided independently:
// recursion over the 2×2 aligned nodes of level ceil(log2 side) at the region's
// aligned corner, each node's min/max and its clipped part's depth sum by
// scanning texels, the same sampled leaves. `sums`: a wholly occluding part's
// depth sum scanned (table: the summed-area table's 4 fetches counted when min
// != max), its node's midpoint (min + max) / 2 times its texels (midpoint), or
// nothing (none). With leaf side 1 and table it must equal brute force.
TraversalResult aligned_traversal_reference(const Image& depth, const SampleTable& table, const Rect& region,
                                            const TraversalParams& params, DepthSums sums);

}  // namespace pn
