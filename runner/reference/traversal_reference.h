// CPU references for glsl/traversal.glsl.
// - brute_force_occluders: the definition — scan every texel of the region,
//   count those with d < t and sum their depths (double).
// - traversal_reference: the same quadtree decisions made independently —
//   recursion instead of a stackless loop, node min/max/mean by scanning the
//   node's texels instead of the pyramid — with Eq. 5 / 6 at sampled leaves
//   computed directly from the same sample table. With leaf side 1 and an
//   unlimited budget it must equal brute force.
#pragma once

#include "core/image.h"
#include "sampling/sample_table.h"
#include "traversal.h"  // glsl/traversal.h: the leaf modes PN_LEAF_*, shared with the shaders

namespace pn {

enum class LeafMode { sampled = PN_LEAF_SAMPLED, min = PN_LEAF_MIN };

struct Rect {
  int x = 0, y = 0, width = 0, height = 0;
};

struct TraversalParams {
  float receiver_depth = 0.0f;
  float bias = 0.0f;
  int leaf_side = 1;
  LeafMode leaf_mode = LeafMode::sampled;
  int node_budget = 1 << 26;
  int pixel_x = 0, pixel_y = 0;
};

struct TraversalResult {
  double occluders = 0.0;
  double depth_sum = 0.0;
  double texels = 0.0;
  long nodes = 0;
  long fetches = 0;

  double blocker_mean() const { return occluders > 0 ? depth_sum / occluders : 0.0; }
  double occluded_fraction() const { return texels > 0 ? occluders / texels : 0.0; }
};

// `depth` is a sanitized N×N map (sanitized_depths); `region` lies inside it.
TraversalResult brute_force_occluders(const Image& depth, const Rect& region, float receiver_depth, float bias);

// `max_level` is the pyramid's last level (nodes above it are not classified).
TraversalResult traversal_reference(const Image& depth, int max_level, const SampleTable& table, const Rect& region,
                                    const TraversalParams& params);

}  // namespace pn
