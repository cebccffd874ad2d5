#include "reference/reuse_reference.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/format.h"

namespace pn {

namespace {

// |a − b| / max(|a|, |b|) <= sigma, the larger value as divisor; both zero are equal.
bool close(float a, float b, float sigma) {
  const float larger = std::fmax(std::fabs(a), std::fabs(b));
  if (larger == 0.0f) return true;
  return std::fabs(a - b) / larger <= sigma;
}

}  // namespace

bool reuse_similar(const float a[4], const float b[4], const ReuseParams& p) {
  return close(a[3], b[3], p.sigma1) && close(a[1], b[1], p.sigma2) && close(a[2], b[2], p.sigma2) &&
         close(a[0], b[0], p.sigma3);
}

std::vector<int> reuse_parents(const Image& entries, const ReuseParams& params) {
  const int w = entries.width, h = entries.height, k = params.tile;
  std::vector<int> parents(static_cast<size_t>(w) * h, -1);
  const auto entry = [&](int x, int y, float out[4]) {
    for (int c = 0; c < 4; ++c) out[c] = entries.at(x, y, c);
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float self[4], other[4];
      entry(x, y, self);
      int parent = -1;
      if (x % k != 0) {
        entry(x - 1, y, other);
        if (reuse_similar(self, other, params)) parent = y * w + x - 1;
      }
      if (parent < 0 && y % k != 0) {
        entry(x, y - 1, other);
        if (reuse_similar(self, other, params)) parent = (y - 1) * w + x;
      }
      parents[static_cast<size_t>(y) * w + x] = parent;
    }
  return parents;
}

std::vector<int> reuse_roots(const std::vector<int>& parents) {
  std::vector<int> roots(parents.size());
  for (size_t i = 0; i < parents.size(); ++i) {
    int r = static_cast<int>(i);
    while (parents[static_cast<size_t>(r)] >= 0) r = parents[static_cast<size_t>(r)];
    roots[i] = r;
  }
  return roots;
}

}  // namespace pn
