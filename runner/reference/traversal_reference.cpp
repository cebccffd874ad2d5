#include "reference/traversal_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

namespace {

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
    const bool spent = r_.nodes >= std::clamp(p_.node_budget, 1, 1 << 26);
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
        else if (p_.leaf_mode == LeafMode::min) r_.occluders += texels, r_.depth_sum += lo * texels;
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

  // Eq. 5 and 6 over the w×h rectangle at (x, y) with the §3.2 samples of a node of side `side`.
  void sample(int x, int y, int w, int h, int side) {
    const SampleSelection s = select_samples(side, p_.pixel_x, p_.pixel_y);
    int occluding = 0;
    float depth_sum = 0.0f;
    for (int column = s.first_column; column <= s.last_column; ++column) {
      const Sample& q = table_.at(column, s.set);
      const int tx = x + std::clamp(static_cast<int>(std::floor(q.x * static_cast<float>(w))), 0, w - 1);
      const int ty = y + std::clamp(static_cast<int>(std::floor(q.y * static_cast<float>(h))), 0, h - 1);
      ++r_.fetches;
      const float d = depth_.at(tx, ty);
      if (d < t_) ++occluding, depth_sum += d;
    }
    const double texels = static_cast<double>(w) * h;
    r_.occluders += texels * occluding / s.count;
    r_.depth_sum += texels * depth_sum / s.count;
  }

  const Image& depth_;
  int max_level_;
  const SampleTable& table_;
  Rect region_;
  TraversalParams p_;
  float t_;
  TraversalResult r_;
};

}  // namespace

TraversalResult traversal_reference(const Image& depth, int max_level, const SampleTable& table, const Rect& region,
                                    const TraversalParams& params) {
  return Recursion(depth, max_level, table, region, params).run();
}

}  // namespace pn
