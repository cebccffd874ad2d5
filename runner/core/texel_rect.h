// Rectangles of texels, rows counted as the map's (from its first row), in
// the two forms the runner uses: TexelRect by its corners, [x0, x1) × [y0, y1)
// (what a shadow-map cache redraws, composes and updates), and Rect by its
// origin and size (a module's region, window or query rectangle).
#pragma once

#include <algorithm>
#include <vector>

namespace pn {

// Origin and size: a region, a PCF window, a summed-area query. It may lie
// partly or wholly outside the map; a width or height <= 0 is empty.
struct Rect {
  int x = 0, y = 0;
  int width = 0, height = 0;
};

struct TexelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  bool empty() const { return x1 <= x0 || y1 <= y0; }
  long long area() const { return empty() ? 0 : static_cast<long long>(x1 - x0) * (y1 - y0); }
  bool operator==(const TexelRect& o) const { return x0 == o.x0 && y0 == o.y0 && x1 == o.x1 && y1 == o.y1; }

  static TexelRect square(int n) { return {0, 0, n, n}; }
};

// The smallest rectangle holding both (an empty one holds nothing).
inline TexelRect bounding(const TexelRect& a, const TexelRect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

inline TexelRect intersection(const TexelRect& a, const TexelRect& b) {
  const TexelRect r{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
  return r.empty() ? TexelRect{} : r;
}

inline bool overlap(const TexelRect& a, const TexelRect& b) { return !intersection(a, b).empty(); }

// The rectangles' areas summed (a texel two of them hold counts twice).
inline long long total_area(const std::vector<TexelRect>& rects) {
  long long a = 0;
  for (const TexelRect& r : rects) a += r.area();
  return a;
}

// total_area as a share of an n×n map, at most 1.
inline double map_share(const std::vector<TexelRect>& rects, int n) {
  return std::min(1.0, static_cast<double>(total_area(rects)) / (static_cast<double>(n) * n));
}

// The rectangles with the empty ones dropped and overlapping ones replaced by
// their bounding rectangle until none overlap; more than `max_count` left
// become their one bounding rectangle. O(n²) a pass.
inline std::vector<TexelRect> merged_rects(std::vector<TexelRect> rects, size_t max_count) {
  rects.erase(std::remove_if(rects.begin(), rects.end(), [](const TexelRect& r) { return r.empty(); }), rects.end());
  for (bool merged = true; merged;) {
    merged = false;
    for (size_t i = 0; i < rects.size(); ++i)
      for (size_t j = i + 1; j < rects.size(); ++j)
        if (overlap(rects[i], rects[j])) {
          rects[i] = bounding(rects[i], rects[j]);
          rects.erase(rects.begin() + static_cast<std::ptrdiff_t>(j));
          merged = true;
          j = i;  // rects[i] grew: look again from its next
        }
  }
  if (rects.size() > max_count) {
    TexelRect all;
    for (const TexelRect& r : rects) all = bounding(all, r);
    rects = {all};
  }
  return rects;
}

}  // namespace pn
