#include "reference/traversal_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "minmax_mip.h"  // PN_MIP_FIRST_LEVEL
#include "reference/pcf_reference.h"
#include "reference/receiver_plane_reference.h"

namespace pn {

TraversalResult brute_force_occluders(const Image& depth, const Rect& region, float receiver_depth, float bias) {
  TraversalResult r;
  r.texels = static_cast<double>(region.width) * region.height;
  const float t = receiver_depth - bias;
  for (int y = region.y; y < region.y + region.height; ++y)
    for (int x = region.x; x < region.x + region.width; ++x) {
      const float d = depth.at(x, y);
      if (d < t) r.occluders += 1.0, r.depth_sum += d;
    }
  return r;
}

TraversalResult brute_force_area_occluders(const Image& depth, double x, double y, double side, float receiver_depth,
                                           float bias) {
  TraversalResult r;
  const float t = receiver_depth - bias;
  for_each_area_texel(depth.width, depth.height, x, y, side, [&](int i, int j, double w) {
    const float d = depth.at(i, j);
    r.texels += w;
    if (d < t) r.occluders += w, r.depth_sum += w * d;
  });
  return r;
}

PlaneOccluders brute_force_occluders_plane(const Image& depth, const Rect& region, double u, double v,
                                           double receiver_depth, double gradient_u, double gradient_v, double bias,
                                           double band) {
  PlaneOccluders r;
  r.certain.texels = static_cast<double>(region.width) * region.height;
  const double t0 = receiver_depth - bias;
  for (int y = region.y; y < region.y + region.height; ++y)
    for (int x = region.x; x < region.x + region.width; ++x) {
      const double d = depth.at(x, y);
      const double t = receiver_plane_threshold(t0, gradient_u * (x + 0.5 - u) + gradient_v * (y + 0.5 - v));
      const double width = band * (std::fabs(t0) + std::fabs(gradient_u) * (std::abs(x) + std::fabs(u) + 1.0) +
                                   std::fabs(gradient_v) * (std::abs(y) + std::fabs(v) + 1.0));
      if (std::fabs(d - t) <= width) {
        r.open += 1.0;
        (d < 0 ? r.open_depth_lo : r.open_depth_hi) += d;
      } else if (d < t) {
        r.certain.occluders += 1.0, r.certain.depth_sum += d;
      }
    }
  return r;
}

namespace {

// An ambiguous leaf of `texels` texels with depths in [lo, hi], lo < t <= hi, estimated without
// samples (traversal.h): min — every texel occludes at lo; ramp — the depths spread evenly over
// [lo, hi], so (t - lo) / (hi - lo) of them occlude, at mean (lo + t) / 2 (half of them, hi = +Inf).
void estimate_leaf(LeafMode mode, double lo, double hi, double texels, double t, TraversalResult& r) {
  if (mode == LeafMode::min) {
    r.occluders += texels, r.depth_sum += lo * texels;
    return;
  }
  const double fraction = std::isinf(hi) ? 0.5 : std::clamp((t - lo) / (hi - lo), 0.0, 1.0);
  r.occluders += fraction * texels;
  r.depth_sum += fraction * texels * 0.5 * (lo + std::min(t, hi));
}

// Eq. 5 and 6 over the w×h rectangle at (x, y) with the §3.2 samples of a node of side `side` —
// with quad leaves those of a node of side at most 4: the 2×2 group of 4 samples (traversal.h).
void sample_rect(const Image& depth, const SampleTable& table, float t, const TraversalParams& p, int x, int y, int w,
                 int h, int side, TraversalResult& r) {
  const int group_side = p.leaf_mode == LeafMode::quad ? std::min(side, 4) : side;
  const SampleSelection s = select_samples(group_side, p.pixel_x, p.pixel_y);
  int occluding = 0;
  float depth_sum = 0.0f;
  for (int column = s.first_column; column <= s.last_column; ++column) {
    const Sample& q = table.at(column, s.set);
    const int tx = x + std::clamp(static_cast<int>(std::floor(q.x * static_cast<float>(w))), 0, w - 1);
    const int ty = y + std::clamp(static_cast<int>(std::floor(q.y * static_cast<float>(h))), 0, h - 1);
    ++r.fetches;
    const float d = depth.at(tx, ty);
    if (d < t) ++occluding, depth_sum += d;
  }
  const double texels = static_cast<double>(w) * h;
  r.occluders += texels * occluding / s.count;
  r.depth_sum += texels * depth_sum / s.count;
}

class Recursion {
 public:
  Recursion(const Image& depth, int max_level, const SampleTable& table, const Rect& region, const TraversalParams& p)
      : depth_(depth), max_level_(max_level), table_(table), region_(region), p_(p), t_(p.receiver_depth - p.bias) {}

  TraversalResult run() {
    r_.texels = static_cast<double>(region_.width) * region_.height;
    if (std::isnan(t_) || r_.texels == 0) return r_;
    int root = 0;
    while ((1 << root) < std::max(region_.width, region_.height)) ++root;
    visit(root, region_.x, region_.y);
    return r_;
  }

 private:
  void visit(int level, int ox, int oy) {
    const int side = 1 << level;
    ++r_.nodes;
    const int lx = std::max(ox, region_.x), ly = std::max(oy, region_.y);
    const int hx = std::min(ox + side, region_.x + region_.width), hy = std::min(oy + side, region_.y + region_.height);
    if (lx >= hx || ly >= hy) return;  // outside the region
    const bool inside = lx == ox && ly == oy && hx == ox + side && hy == oy + side;
    const bool spent = r_.nodes >= std::clamp(p_.node_budget, 1, PN_TRAVERSAL_NO_BUDGET);
    if (inside && level <= max_level_) {
      ++r_.fetches;
      float lo = std::numeric_limits<float>::infinity(), hi = -lo;
      double sum = 0.0;
      for (int y = oy; y < oy + side; ++y)
        for (int x = ox; x < ox + side; ++x) lo = std::min(lo, depth_.at(x, y)), hi = std::max(hi, depth_.at(x, y)), sum += depth_.at(x, y);
      const double texels = static_cast<double>(side) * side;
      if (hi < t_) {  // every texel occludes
        r_.occluders += texels;
        r_.depth_sum += sum;
      } else if (lo < t_) {  // some do
        if (side > p_.leaf_side && !spent) children(level, ox, oy);
        else if (!sampled_leaves(p_.leaf_mode)) estimate_leaf(p_.leaf_mode, lo, hi, texels, t_, r_);
        else sample(ox, oy, side, side, side);
      }
    } else if (!spent) {
      children(level, ox, oy);
    } else {
      sample(lx, ly, hx - lx, hy - ly, side);
    }
  }

  void children(int level, int ox, int oy) {
    const int h = 1 << (level - 1);
    visit(level - 1, ox, oy);
    visit(level - 1, ox + h, oy);
    visit(level - 1, ox, oy + h);
    visit(level - 1, ox + h, oy + h);
  }

  void sample(int x, int y, int w, int h, int side) { sample_rect(depth_, table_, t_, p_, x, y, w, h, side, r_); }

  const Image& depth_;
  int max_level_;
  const SampleTable& table_;
  Rect region_;
  TraversalParams p_;
  float t_;
  TraversalResult r_;
};

// The (min, max) depth of the aligned node of side `side` at (ox, oy), over its texels in the map.
std::pair<float, float> node_range(const Image& depth, int ox, int oy, int side) {
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (int y = oy; y < std::min(oy + side, depth.height); ++y)
    for (int x = ox; x < std::min(ox + side, depth.width); ++x) lo = std::min(lo, depth.at(x, y)), hi = std::max(hi, depth.at(x, y));
  return {lo, hi};
}

// A wholly occluding node's clipped part [lx, hx) × [ly, hy): its texels, and its depth sum as
// `sums` says (scanned, with the table's four fetches when lo != hi; the midpoint; none).
void add_occluding_part(const Image& depth, int lx, int ly, int hx, int hy, float lo, float hi, DepthSums sums,
                        TraversalResult& r) {
  const double texels = static_cast<double>(hx - lx) * (hy - ly);
  r.occluders += texels;
  if (sums == DepthSums::none) return;
  if (sums == DepthSums::midpoint && lo != hi) {
    r.depth_sum += 0.5 * (static_cast<double>(lo) + hi) * texels;
    return;
  }
  for (int y = ly; y < hy; ++y)
    for (int x = lx; x < hx; ++x) r.depth_sum += depth.at(x, y);
  if (lo != hi) r.fetches += 4;  // the table's four corners
}

// The chain keeps nodes of side 4 and up (minmax_mip.glsl): a smaller node is decided by the range
// of the side-4 node that holds it — a superset of its texels.
constexpr int kKeptSide = 1 << PN_MIP_FIRST_LEVEL;

std::pair<float, float> kept_node_range(const Image& depth, int ox, int oy, int side) {
  if (side >= kKeptSide) return node_range(depth, ox, oy, side);
  return node_range(depth, ox / kKeptSide * kKeptSide, oy / kKeptSide * kKeptSide, kKeptSide);
}

// Over aligned nodes clipped to the region (minmax_mip.glsl's chain).
class AlignedRecursion {
 public:
  AlignedRecursion(const Image& depth, const SampleTable& table, const Rect& region, const TraversalParams& p,
                   DepthSums sums)
      : depth_(depth), table_(table), region_(region), p_(p), t_(p.receiver_depth - p.bias), sums_(sums) {}

  TraversalResult run() {
    r_.texels = static_cast<double>(region_.width) * region_.height;
    if (std::isnan(t_) || r_.texels == 0) return r_;
    int padded = kKeptSide, top = 0;
    while (padded < std::max(depth_.width, depth_.height)) padded *= 2;
    while ((1 << top) < std::max(region_.width, region_.height)) ++top;
    while ((1 << top) > padded) --top;
    const int ox = region_.x >> top << top, oy = region_.y >> top << top, s = 1 << top;
    visit(top, ox, oy);
    visit(top, ox + s, oy);
    visit(top, ox, oy + s);
    visit(top, ox + s, oy + s);
    return r_;
  }

 private:
  struct Part {
    int lx, ly, hx, hy;
    double texels() const { return static_cast<double>(hx - lx) * (hy - ly); }
  };

  void visit(int level, int ox, int oy) {
    const int side = 1 << level;
    const Part part{std::max(ox, region_.x), std::max(oy, region_.y), std::min(ox + side, region_.x + region_.width),
                    std::min(oy + side, region_.y + region_.height)};
    if (part.lx >= part.hx || part.ly >= part.hy) {
      ++r_.nodes;  // outside the region
      return;
    }
    const bool spent = r_.nodes + 1 >= std::clamp(p_.node_budget, 1, PN_TRAVERSAL_NO_BUDGET);
    ++r_.nodes;
    ++r_.fetches;
    const auto [lo, hi] = kept_node_range(depth_, ox, oy, side);
    if (hi < t_) {  // every texel occludes: the part's count and depth sum
      add_occluding_part(depth_, part.lx, part.ly, part.hx, part.hy, lo, hi, sums_, r_);
      return;
    }
    if (!(lo < t_)) return;  // none does
    if (side <= p_.leaf_side || spent) {
      if (!sampled_leaves(p_.leaf_mode)) estimate_leaf(p_.leaf_mode, lo, hi, part.texels(), t_, r_);
      else sample(part, side);
    } else if (level == 1) {  // four texels, classified at once
      r_.nodes += 4;
      r_.fetches += 4;  // the map's four texels
      for (int y = part.ly; y < part.hy; ++y)
        for (int x = part.lx; x < part.hx; ++x)
          if (depth_.at(x, y) < t_) r_.occluders += 1.0, r_.depth_sum += sums_ == DepthSums::none ? 0.0 : depth_.at(x, y);
    } else {
      const int h = side / 2;
      visit(level - 1, ox, oy);
      visit(level - 1, ox + h, oy);
      visit(level - 1, ox, oy + h);
      visit(level - 1, ox + h, oy + h);
    }
  }

  void sample(const Part& part, int side) {
    sample_rect(depth_, table_, t_, p_, part.lx, part.ly, part.hx - part.lx, part.hy - part.ly, side, r_);
  }

  const Image& depth_;
  const SampleTable& table_;
  Rect region_;
  TraversalParams p_;
  float t_;
  DepthSums sums_;
  TraversalResult r_;
};

// Over the aligned nodes of one level clipped to the region (pnGridRegionMip).
TraversalResult grid_count(const Image& depth, const SampleTable& table, const Rect& region, const TraversalParams& p,
                           DepthSums sums, int grid) {
  TraversalResult r;
  r.texels = static_cast<double>(region.width) * region.height;
  const float t = p.receiver_depth - p.bias;
  if (std::isnan(t) || r.texels == 0) return r;
  int padded = kKeptSide, max_level = PN_MIP_FIRST_LEVEL;
  while (padded < std::max(depth.width, depth.height)) padded *= 2, ++max_level;
  const int cells = std::clamp(grid, 1, PN_GRID_MAX_CELLS);
  const int wanted = std::max(1, (std::max(region.width, region.height) + cells - 1) / cells);
  int level = 0;
  while ((1 << level) < wanted) ++level;
  level = std::min(level, max_level);
  const int side = 1 << level;
  for (int ny = region.y >> level; ny <= (region.y + region.height - 1) >> level; ++ny)
    for (int nx = region.x >> level; nx <= (region.x + region.width - 1) >> level; ++nx) {
      const int ox = nx * side, oy = ny * side;
      const int lx = std::max(ox, region.x), ly = std::max(oy, region.y);
      const int hx = std::min(ox + side, region.x + region.width), hy = std::min(oy + side, region.y + region.height);
      ++r.nodes, ++r.fetches;
      const auto [lo, hi] = kept_node_range(depth, ox, oy, side);
      if (hi < t) {  // every texel occludes
        add_occluding_part(depth, lx, ly, hx, hy, lo, hi, sums, r);
        continue;
      }
      if (!(lo < t)) continue;
      const double part = static_cast<double>(hx - lx) * (hy - ly);
      if (!sampled_leaves(p.leaf_mode)) estimate_leaf(p.leaf_mode, lo, hi, part, t, r);
      else sample_rect(depth, table, t, p, lx, ly, hx - lx, hy - ly, std::min(side, std::max(p.leaf_side, 1)), r);
    }
  return r;
}

}  // namespace

TraversalResult aligned_grid_reference(const Image& depth, const SampleTable& table, const Rect& region,
                                       const TraversalParams& params, DepthSums sums, int grid) {
  return grid_count(depth, table, region, params, sums, grid);
}

TraversalResult aligned_traversal_reference(const Image& depth, const SampleTable& table, const Rect& region,
                                            const TraversalParams& params, DepthSums sums) {
  return AlignedRecursion(depth, table, region, params, sums).run();
}

TraversalResult traversal_reference(const Image& depth, int max_level, const SampleTable& table, const Rect& region,
                                    const TraversalParams& params) {
  return Recursion(depth, max_level, table, region, params).run();
}

}  // namespace pn
