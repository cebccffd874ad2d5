#include "reference/depth_pyramid_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"

namespace pn {

float sanitize_depth(float depth) {
  return std::isfinite(depth) ? depth : std::numeric_limits<float>::infinity();
}

WindowStats window_stats(const Image& map, int u, int v, int side) {
  WindowStats s{std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(), 0.0};
  double sum = 0.0;
  for (int y = v; y < v + side; ++y) {
    for (int x = u; x < u + side; ++x) {
      const float d = sanitize_depth(map.at(x, y));
      s.min = std::min(s.min, d);
      s.max = std::max(s.max, d);
      sum += d;
    }
  }
  s.mean = sum / (static_cast<double>(side) * side);
  return s;
}

Image sanitized_depths(const Image& map) {
  Image out = map;
  for (float& d : out.texels) d = sanitize_depth(d);
  return out;
}

Image pyramid_level_reference(const Image& map, int level) {
  const Image depth = sanitized_depths(map);
  const int n = map.width, w = 1 << level, size = n - w + 1;
  // Per row y and window column u: min, max and sum of the row segment [u, u + w).
  std::vector<float> seg_min(static_cast<size_t>(n) * size), seg_max(seg_min.size());
  std::vector<double> seg_sum(seg_min.size());
  for (int y = 0; y < n; ++y) {
    const float* row = &depth.texels[static_cast<size_t>(y) * n];
    for (int u = 0; u < size; ++u) {
      float lo = row[u], hi = row[u];
      double sum = 0.0;
      for (int x = u; x < u + w; ++x) lo = std::min(lo, row[x]), hi = std::max(hi, row[x]), sum += row[x];
      const size_t k = static_cast<size_t>(y) * size + u;
      seg_min[k] = lo, seg_max[k] = hi, seg_sum[k] = sum;
    }
  }
  Image out(size, size, 3);
  for (int v = 0; v < size; ++v) {
    for (int u = 0; u < size; ++u) {
      float lo = std::numeric_limits<float>::infinity(), hi = -lo;
      double sum = 0.0;
      for (int y = v; y < v + w; ++y) {
        const size_t k = static_cast<size_t>(y) * size + u;
        lo = std::min(lo, seg_min[k]), hi = std::max(hi, seg_max[k]), sum += seg_sum[k];
      }
      out.at(u, v, 0) = lo;
      out.at(u, v, 1) = hi;
      out.at(u, v, 2) = static_cast<float>(sum / (static_cast<double>(w) * w));
    }
  }
  return out;
}

std::pair<float, float> square_min_max(const Image& depth, int u, int v, int side) {
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (int y = v; y < v + side; ++y) {
    const float* row = &depth.texels[static_cast<size_t>(y) * depth.width];
    for (int x = u; x < u + side; ++x) lo = std::min(lo, row[x]), hi = std::max(hi, row[x]);
  }
  return {lo, hi};
}

}  // namespace pn
