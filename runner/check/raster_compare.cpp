#include "check/raster_compare.h"

#include <algorithm>
#include <cmath>

namespace pn {
namespace {

double scale(double v) { return std::max(std::fabs(v), 1.0); }

bool same(float e, float o, double relative) {
  if (std::isinf(e) || std::isinf(o)) return e == o;
  return std::fabs(static_cast<double>(e) - o) <= relative * scale(e);
}

}  // namespace

SilhouetteRule within_neighbour_range(const Image& expected, const Image& observed, double sliver) {
  return [&expected, &observed, sliver](int x, int y) {
    for (int c = 0; c < expected.channels; ++c) {
      double lo = INFINITY, hi = -INFINITY;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (x + dx >= 0 && x + dx < expected.width && y + dy >= 0 && y + dy < expected.height)
            lo = std::min(lo, double(expected.at(x + dx, y + dy, c))), hi = std::max(hi, double(expected.at(x + dx, y + dy, c)));
      const double o = observed.at(x, y, c);
      if (!(std::isinf(o) ? o == hi : (o >= lo - sliver * scale(lo) && o <= hi + sliver * scale(hi)))) return false;
    }
    return true;
  };
}

std::vector<CaseResult> compare_raster(const std::string& name, const Image& expected, const Image& observed,
                                       double relative, const SilhouetteRule& explained, const std::string& rule) {
  const int w = expected.width, h = expected.height, channels = expected.channels;
  Image masked_expected = expected, masked_observed = observed, within(w, h, 1, 1.0f);
  int silhouette = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool agree = true;
      for (int c = 0; c < channels; ++c) agree = agree && same(expected.at(x, y, c), observed.at(x, y, c), relative);
      if (agree) continue;
      ++silhouette;
      within.at(x, y) = explained(x, y) ? 1.0f : 0.0f;
      for (int c = 0; c < channels; ++c) masked_expected.at(x, y, c) = masked_observed.at(x, y, c) = 0.0f;
    }
  // The off-silhouette bound as one absolute number: `relative` of the largest finite value.
  const Tolerance off = Tolerance::absolute(relative * largest_finite_magnitude(expected, 1.0f));
  return {{name + " off silhouettes (" + std::to_string(silhouette) + " silhouette pixels)", off,
           compare(masked_expected, masked_observed, off)},
          {name + ": every silhouette pixel " + rule, Tolerance::exact(),
           compare(Image(w, h, 1, 1.0f), within, Tolerance::exact())}};
}

}  // namespace pn
