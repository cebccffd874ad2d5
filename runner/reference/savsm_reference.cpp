#include "reference/savsm_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/format.h"
#include "minmax_mip.h"  // PN_MIP_FIRST_LEVEL
#include "reference/pcf_reference.h"
#include "reference/pcss_regions_reference.h"  // pcss_square

namespace pn {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

bool empty(const Rect& r) { return r.width <= 0 || r.height <= 0; }

}  // namespace

SavsmMoments savsm_rect_moments(const Image& depth, const Rect& rect, double near_depth, double far_depth) {
  SavsmMoments m;
  const int x0 = std::max(rect.x, 0), y0 = std::max(rect.y, 0);
  const int x1 = std::min(rect.x + std::max(rect.width, 0), depth.width);
  const int y1 = std::min(rect.y + std::max(rect.height, 0), depth.height);
  if (x1 <= x0 || y1 <= y0) return m;
  const auto value = [&](int x, int y) {
    const double d = depth.at(x, y);
    return std::isfinite(d) ? std::clamp(d, near_depth, far_depth) : far_depth;
  };
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) sum += value(x, y);
  m.texels = static_cast<long>(x1 - x0) * (y1 - y0);
  m.mean = sum / static_cast<double>(m.texels);
  double squares = 0.0;  // two-pass: no cancellation
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) squares += (value(x, y) - m.mean) * (value(x, y) - m.mean);
  m.variance = squares / static_cast<double>(m.texels);
  return m;
}

SavsmBlockerEstimate savsm_blocker_from_moments(double mean, double variance, double t, double min_variance,
                                                double near_depth) {
  SavsmBlockerEstimate e;
  const double p = chebyshev_bound_variance(mean, variance, t, min_variance);
  e.has = p < 1.0 - kSavsmMinOccluded;
  if (!e.has) return e;
  e.depth = std::clamp(mean - floored_variance(mean, variance, min_variance) / (t - mean), near_depth, t);
  return e;
}

DepthRange savsm_square_range(const Image& depth, const Rect& rect) {
  const Rect c = mip_square_cover(rect, depth.width);
  DepthRange r{kInf, -kInf};
  for (int y = c.y; y < c.y + c.height; ++y)
    for (int x = c.x; x < c.x + c.width; ++x) {
      const float d = depth.at(x, y);
      const float v = std::isfinite(d) ? d : kInf;
      r.min = std::min(r.min, v);
      r.max = std::max(r.max, v);
    }
  return r;
}

SavsmEstimate savsm_reference(const Image& depth, const LightModel& light, const SavsmReceiver& receiver,
                              const SavsmSettings& settings, const Rect* search, const Rect* filter) {
  SavsmEstimate e;
  const float dP = receiver.depth;
  if (!std::isfinite(dP) || !std::isfinite(receiver.u) || !std::isfinite(receiver.v)) return e;
  const int n = depth.width;
  // t as the module forms it, in float: the lit decisions compare it with stored floats.
  const float t = dP - settings.bias;
  e.search = search ? *search : pcss_square(receiver.u, receiver.v, light.search_width_texels(dP), n, nullptr);
  if (empty(e.search)) return e;
  e.surface = true;
  const DepthRange search_range = savsm_square_range(depth, e.search);
  if (settings.bound && t <= search_range.min) {
    e.lit_by_bound = true;
    return e;
  }
  if (settings.blocker == SavsmBlocker::min) {
    e.has_blocker = search_range.min < t;
    e.blocker = e.has_blocker ? search_range.min : 0.0;
  } else {
    const SavsmMoments s = savsm_rect_moments(depth, e.search, light.near_plane, light.far_plane);
    const SavsmBlockerEstimate b = savsm_blocker_from_moments(s.mean, s.variance, t, settings.min_variance, light.near_plane);
    e.has_blocker = b.has;
    e.blocker = b.depth;
  }
  if (!e.has_blocker) return e;
  e.filter_side = settings.filter_scale * light.penumbra_texels(dP, e.blocker);
  e.filter = filter ? *filter : pcss_square(receiver.u, receiver.v, e.filter_side, n, nullptr);
  if (empty(e.filter)) return e;
  e.filter_moments = savsm_rect_moments(depth, e.filter, light.near_plane, light.far_plane);
  e.chebyshev = chebyshev_bound_variance(e.filter_moments.mean, e.filter_moments.variance, t, settings.min_variance);
  e.reduced = reduce_bleeding(e.chebyshev, settings.bleeding_reduction);
  e.bound = settings.bound ? depth_range_bound(savsm_square_range(depth, e.filter), t) : PN_VSM_BOUND_NONE;
  e.visibility = vsm_visibility(e.bound, e.reduced);
  return e;
}

double savsm_pcf_visibility(const Image& depth, const Rect& rect, float t) {
  return 1.0 - pcf_reference(depth, {rect.x, rect.y, rect.width, rect.height}, t, 0.0).occluded_fraction();
}

int savsm_square_fetches(const Rect& rect, int n) {
  const Rect c = mip_square_cover(rect, n);
  if (c.width <= 0 || c.height <= 0) return 0;
  // The cover's nodes have the side 2^l of pnMipSquareMinMax's level (a power of two; the last
  // node on an axis may be cut by the map's edge): one fetch each.
  const int side = std::max(rect.width, rect.height), clipped = std::max(std::min(rect.x + side, n) - rect.x,
                                                                         std::min(rect.y + side, n) - rect.y);
  int node = 1 << PN_MIP_FIRST_LEVEL;  // the chain's first level's side
  while (2 * node < clipped) node *= 2;
  const auto count = [node](int from, int length) { return (from + length - 1) / node - from / node + 1; };
  return count(c.x, c.width) * count(c.y, c.height);
}

int savsm_fetches(const SavsmEstimate& e, const SavsmSettings& settings, int n) {
  if (!e.surface) return 0;
  int fetches = settings.reads_mip() ? savsm_square_fetches(e.search, n) : 0;
  if (e.lit_by_bound) return fetches;
  if (settings.blocker == SavsmBlocker::table) fetches += kSavsmRectFetches;
  if (!e.has_blocker || empty(e.filter)) return fetches;
  return fetches + kSavsmRectFetches + (settings.bound ? savsm_square_fetches(e.filter, n) : 0);
}

}  // namespace pn
