// C++ face of glsl/traversal.glsl: the structure it walks, its leaf modes and
// depth sums, one query's parameters and what a traversal counts — shared by
// the traversal pass, the pipeline's settings and the traversal's reference.
#pragma once

#include <traversal.h>  // glsl/traversal.h: PN_LEAF_*, PN_DEPTH_SUMS_*, PN_STRUCTURE_*, shared with the shaders

namespace pn {

enum class LeafMode { sampled = PN_LEAF_SAMPLED, min = PN_LEAF_MIN, ramp = PN_LEAF_RAMP, quad = PN_LEAF_QUAD };

// Whether a leaf mode samples the leaf from the sample table (sampled, quad: traversal.h).
inline bool sampled_leaves(LeafMode mode) { return mode == LeafMode::sampled || mode == LeafMode::quad; }

// The depth sums of the mip chain's wholly occluding nodes (glsl/traversal.h).
enum class DepthSums { none = PN_DEPTH_SUMS_NONE, table = PN_DEPTH_SUMS_TABLE, midpoint = PN_DEPTH_SUMS_MIDPOINT };

// What Steps 3-5 read from the shadow map (traversal.h): the paper's
// decreased pyramid (depth_pyramid.glsl, N² texels a level), or the aligned
// min/max mip chain (minmax_mip.glsl, 4/3 N²) with a summed-area table of
// depth (summed_area.glsl) for the blocker mean's clipped sums.
enum class Structure {
  pyramid = PN_STRUCTURE_PYRAMID,
  mip = PN_STRUCTURE_MIP,
};

struct TraversalParams {
  float receiver_depth = 0.0f;
  float bias = 0.0f;
  int leaf_side = 1;
  LeafMode leaf_mode = LeafMode::sampled;
  int node_budget = PN_TRAVERSAL_NO_BUDGET;
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

}  // namespace pn
