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
#include "sampling/sample_table_generator.h"
#include "modules/traversal_face.h"

namespace pn {

// `depth` is a sanitized N×N map (sanitized_depths); `region` lies inside it.
TraversalResult brute_force_occluders(const Image& depth, const Rect& region, float receiver_depth, float bias);
// The same over the area-weighted square of side `side` centred on (x, y) (pnRegionArea, issue 51):
// every texel weighed by its overlap (for_each_area_texel), texels = the square's area in the map.
TraversalResult brute_force_area_occluders(const Image& depth, double x, double y, double side, float receiver_depth,
                                           float bias);

// The definition with a receiver plane (glsl/receiver_plane.glsl), in double: texel q occludes when
// d(q) < receiver_depth - bias + g · (q + ½ − (u, v)). A texel whose depth lies within
// `band` · (|receiver_depth - bias| + |g.u| (|q.x| + |u| + 1) + |g.v| (|q.y| + |v| + 1)) of its threshold
// — where a float evaluation may round either way — is left open: counted in `open`, its depth in
// open_depth_lo (if negative) or open_depth_hi; `certain` holds the others.
struct PlaneOccluders {
  TraversalResult certain;
  double open = 0.0, open_depth_lo = 0.0, open_depth_hi = 0.0;
};
PlaneOccluders brute_force_occluders_plane(const Image& depth, const Rect& region, double u, double v,
                                           double receiver_depth, double gradient_u, double gradient_v, double bias,
                                           double band);

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

// pnGridRegionMip, decided independently: the aligned nodes of level ceil(log2 ceil(side / grid))
// (capped at the chain's last level) that touch the region, each node's min / max by scanning its
// texels, a wholly occluding part's sum as `sums` says, an ambiguous node a leaf — the §3.2
// samples of the group for min(node side, leaf side), or the leaf mode's estimate at the part's
// centre. With grid >= the region's side it must equal brute force.
TraversalResult aligned_grid_reference(const Image& depth, const SampleTable& table, const Rect& region,
                                       const TraversalParams& params, DepthSums sums, int grid);

}  // namespace pn
