// CPU definition of the counts pnFastPcssEstimate reports (glsl/fast_pcss.glsl's PnFastPcssResult:
// blockerNodes, occlusionNodes, fetches) for the shipped walk (exact squares over the aligned mip
// chain, sampled leaves, midpoint depth sums; or the ablations' with a node budget), composed from the steps' own references, never
// ported from the walk:
// - Step 3: search_entry over the mip chain (pcss_regions_reference.h), its refinements each 9
//   fetches (the 3×3 nodes a refinement reads, at their bound);
// - Step 4: aligned_traversal_reference (traversal_reference.h, a recursion) over the search
//   entry's square, midpoint sums, leaves of at least the square's longer side / the leaf divisor;
// - Step 5: filter_entry from its blocker mean, then the same traversal of the filter square
//   without sums;
// - fetches = 9 · refinements + both traversals' fetches (a node read, a sample read).
#pragma once

#include "core/image.h"
#include "modules/traversal_face.h"
#include "sampling/sample_table_generator.h"
#include "scene/light_model.h"

namespace pn {

struct FastPcssCountSettings {
  float bias = 0.0f;
  double filter_scale = 1.0;
  int refine_iterations = 0;
  int leaf_side = 1;      // leaves at least this side
  int leaf_divisor = 0;   // > 0: leaves at least a square's longer side / this (the work budget)
  LeafMode leaf_mode = LeafMode::sampled;
  int node_budget = PN_TRAVERSAL_NO_BUDGET;  // a traversal's (traversal.glsl)
};

struct FastPcssCounts {
  Image blocker_nodes, occlusion_nodes, fetches;  // one channel each, a G-buffer pixel each
  Image ambiguous;  // 1 where a decision lay within `margin` (relative) of flipping: float may differ
};

// For each pixel of `gbuffer` (u, v, light depth, valid) on `shadow_map` (n×n light depths).
FastPcssCounts fast_pcss_counts_reference(const Image& shadow_map, const Image& gbuffer, const LightModel& light,
                                          const SampleTable& table, const FastPcssCountSettings& settings,
                                          double margin);

}  // namespace pn
