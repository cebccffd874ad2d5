#include "reference/fast_pcss_reference.h"

#include <algorithm>

#include "reference/pcss_regions_reference.h"
#include "reference/traversal_reference.h"

namespace pn {

namespace {

// Fetches a refinement of Step 3 counts: the 3×3 aligned nodes of the square's level, at their bound.
constexpr int kRefinementFetches = 9;

// The leaf side a square is walked with: settings' side, or its longer side / the divisor if larger.
int leaf_side_for(const Rect& square, const FastPcssCountSettings& s) {
  return s.leaf_divisor > 0 ? std::max(s.leaf_side, std::max(square.width, square.height) / s.leaf_divisor)
                            : s.leaf_side;
}

}  // namespace

FastPcssCounts fast_pcss_counts_reference(const Image& shadow_map, const Image& gbuffer, const LightModel& light,
                                          const SampleTable& table, const FastPcssCountSettings& settings,
                                          double margin) {
  const DepthScan scan(shadow_map);
  const int n = scan.size();
  const int w = gbuffer.width, h = gbuffer.height;
  FastPcssCounts out{Image(w, h, 1, 0.0f), Image(w, h, 1, 0.0f), Image(w, h, 1, 0.0f), Image(w, h, 1, 0.0f)};
  for (int py = 0; py < h; ++py)
    for (int px = 0; px < w; ++px) {
      const RegionReceiver receiver{gbuffer.at(px, py, 0), gbuffer.at(px, py, 1), gbuffer.at(px, py, 2),
                                    gbuffer.at(px, py, 3)};
      Rounding rounding{margin};
      int refinements = 0;
      const RegionEntry search = search_entry(scan, light, receiver, settings.bias, settings.refine_iterations,
                                              &rounding, Structure::mip, &refinements);
      double fetches = kRefinementFetches * refinements;
      // One traversal of an entry's square (Step 4 with midpoint sums, Step 5 without).
      const auto traverse = [&](const RegionEntry& entry, DepthSums sums) {
        note_region(entry, n, RegionMode::exact, rounding);
        const Rect square = entry_region(entry, n, RegionMode::exact);
        TraversalParams p;
        p.receiver_depth = receiver.depth, p.bias = settings.bias;
        p.leaf_side = leaf_side_for(square, settings), p.leaf_mode = settings.leaf_mode;
        p.pixel_x = px, p.pixel_y = py, p.node_budget = settings.node_budget;
        const TraversalResult r = aligned_traversal_reference(scan.depths(), table, square, p, sums);
        fetches += static_cast<double>(r.fetches);
        return r;
      };
      if (!search.lit()) {
        const TraversalResult blockers = traverse(search, DepthSums::midpoint);
        out.blocker_nodes.at(px, py) = static_cast<float>(blockers.nodes);
        const RegionEntry filter =
            filter_entry(light, search, blockers.blocker_mean(), blockers.occluders > 0.0, settings.filter_scale);
        if (!filter.lit()) out.occlusion_nodes.at(px, py) = static_cast<float>(traverse(filter, DepthSums::none).nodes);
      }
      out.fetches.at(px, py) = static_cast<float>(fetches);
      out.ambiguous.at(px, py) = rounding.ambiguous ? 1.0f : 0.0f;
    }
  return out;
}

}  // namespace pn
