#include "reference/pcss_regions_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "minmax_mip.h"  // PN_MIP_FIRST_LEVEL
#include "reference/depth_pyramid_reference.h"
#include "reference/region_reference.h"

namespace pn {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Rect window_rect(const RegionWindow& w) { return {w.u, w.v, w.side, w.side}; }

// Distance of v from the nearest integer.
double from_integer(double v) { return std::fabs(v - std::round(v)); }

// The area square's cover: its bounds c ± s/2 floored and ceiled — a bound within rounding of an
// integer may land on either side in float.
void note_area(const RegionEntry& e, int n, Rounding& rounding) {
  const double s = std::clamp(std::isnan(e.side) ? 0.0 : std::max(e.side, 0.0), 1.0, 4.0 * n);
  for (double c : {e.x, e.y})
    for (double bound : {c - 0.5 * s, c + 0.5 * s})
      if (std::isfinite(bound) && from_integer(bound) <= rounding.relative * (std::fabs(c) + s + 1.0))
        rounding.ambiguous = true;
}

}  // namespace

void note_region(const RegionEntry& e, int n, RegionMode mode, Rounding& rounding) {
  const double s = e.side;
  if (!std::isfinite(s) || s < 0.0) return;
  const double rel = rounding.relative;
  if (mode == RegionMode::exact) {
    // m = round(s): its .5 points (GLSL's round() also leaves an exact .5 to the implementation).
    if (std::fabs(std::fabs(s - std::floor(s)) - 0.5) <= rel * s) rounding.ambiguous = true;
    const double m = std::clamp(std::round(s), 1.0, 4.0 * n);
    for (double c : {e.x, e.y}) {
      // The origin floor(c - m/2 + 1/2): exact in float when it is an integer, rounded otherwise.
      const double lo = c - 0.5 * m + 0.5, off = from_integer(lo);
      if (std::isfinite(lo) && off > 0.0 && off <= rel * (std::fabs(c) + m + 1.0)) rounding.ambiguous = true;
    }
    return;
  }
  if (s == 0.0) return;  // both sides evaluate floor(x), ceil(x) of the same float
  for (double c : {e.x, e.y})
    for (double bound : {c - 0.5 * s, c + 0.5 * s})
      if (std::isfinite(bound) && from_integer(bound) <= rel * (std::fabs(c) + s + 1.0)) rounding.ambiguous = true;
}

Rect pcss_square(double x, double y, double side, int n, double* margin) {
  const double s = std::isnan(side) ? 0.0 : std::max(side, 0.0);
  const double size = std::clamp(std::round(s), 1.0, 4.0 * n);
  double closest = std::isfinite(s) ? std::fabs(std::fabs(s - std::floor(s)) - 0.5) : kInf;  // s from a .5 point
  const auto axis = [&](double c, int& start, int& length) {
    const double lo = c - 0.5 * size + 0.5;
    if (std::isfinite(lo)) closest = std::min({closest, lo - std::floor(lo), std::ceil(lo) - lo});
    const double first = std::floor(lo);
    const double a = std::clamp(first, 0.0, static_cast<double>(n));
    const double b = std::clamp(first + size, a, static_cast<double>(n));
    start = static_cast<int>(a);
    length = static_cast<int>(b - a);
  };
  Rect r;
  axis(std::isnan(x) ? 0.0 : x, r.x, r.width);
  axis(std::isnan(y) ? 0.0 : y, r.y, r.height);
  if (margin) *margin = closest;
  return r;
}

Rect entry_region(const RegionEntry& entry, int n, RegionMode mode) {
  const float x = static_cast<float>(entry.x), y = static_cast<float>(entry.y), s = static_cast<float>(entry.side);
  switch (mode) {
    case RegionMode::window: return window_rect(region_reference(x, y, s, n));
    case RegionMode::centred: return window_rect(region_centred_reference(x, y, s, n));
    case RegionMode::exact: break;
  }
  return pcss_square(entry.x, entry.y, entry.side, n, nullptr);
}

Rect area_cover(double x, double y, double side, int n) {
  const double s = std::clamp(std::isnan(side) ? 0.0 : std::max(side, 0.0), 1.0, 4.0 * n);
  const auto axis = [&](double c, int& start, int& length) {
    c = std::clamp(std::isnan(c) ? 0.0 : c, -4.0 * n, 5.0 * n);
    const double lo = std::clamp(c - 0.5 * s, 0.0, static_cast<double>(n));
    const double hi = std::clamp(c + 0.5 * s, lo, static_cast<double>(n));
    start = static_cast<int>(std::floor(lo));
    length = static_cast<int>(std::ceil(hi)) - start;
  };
  Rect r;
  axis(x, r.x, r.width);
  axis(y, r.y, r.height);
  return r;
}

Rect search_min_square(const RegionEntry& entry, int n) {
  return covering_square(pcss_square(entry.x, entry.y, entry.side, n, nullptr), n);
}

Rect covering_square(const Rect& r, int n) {
  if (r.width == 0 || r.height == 0) return Rect{};
  const int side = std::min(std::max(r.width, r.height), n);
  return {std::clamp(r.x, 0, n - side), std::clamp(r.y, 0, n - side), side, side};
}

Rect mip_search_cover(const RegionEntry& entry, int n) {
  return mip_square_cover(pcss_square(entry.x, entry.y, entry.side, n, nullptr), n);
}

Rect mip_square_cover(const Rect& r, int n) {
  if (r.width <= 0 || r.height <= 0) return Rect{};
  const int side = std::max(r.width, r.height);
  const int x1 = std::min(r.x + side, n), y1 = std::min(r.y + side, n);
  int level = PN_MIP_FIRST_LEVEL;  // the chain's first level: nodes of side 4 and up
  while ((2 << level) < std::max(x1 - r.x, y1 - r.y)) ++level;  // 2^(level+1) >= m
  const int x0 = r.x >> level << level, y0 = r.y >> level << level;
  const int x2 = std::min((((x1 - 1) >> level) + 1) << level, n), y2 = std::min((((y1 - 1) >> level) + 1) << level, n);
  return {x0, y0, x2 - x0, y2 - y0};
}

DepthScan::DepthScan(const Image& map) : depths_(sanitized_depths(map)) {}

double DepthScan::min(const Rect& r) const {
  if (r.width <= 0 || r.height <= 0) return kInf;
  const std::uint64_t key = (static_cast<std::uint64_t>(r.x) << 48) | (static_cast<std::uint64_t>(r.y) << 32) |
                            (static_cast<std::uint64_t>(r.width) << 16) | static_cast<std::uint64_t>(r.height);
  const auto found = mins_.find(key);
  if (found != mins_.end()) return found->second;
  float lo = std::numeric_limits<float>::infinity();
  for (int y = r.y; y < r.y + r.height; ++y)
    for (int x = r.x; x < r.x + r.width; ++x) lo = std::min(lo, depths_.at(x, y));
  mins_.emplace(key, lo);
  return lo;
}

RegionEntry search_entry(const DepthScan& scan, const LightModel& light, const RegionReceiver& receiver, double bias,
                         int iterations, Rounding* rounding, Structure structure, int* refinements, bool area_edges,
                         std::array<double, 2> gradient) {
  int reads = 0;
  if (!refinements) refinements = &reads;
  *refinements = 0;
  const double d = receiver.depth;
  if (receiver.valid == 0.0f || std::isnan(d)) return {0.0, 0.0, 0.0, kRegionLit};
  const int n = scan.size();
  const double threshold = d - bias;
  RegionEntry e{d, receiver.u, receiver.v, light.search_width_texels(d)};
  for (int i = 0; i < std::min(iterations, kRefineMaxIterations); ++i) {
    if (rounding && !area_edges) note_region(e, n, RegionMode::exact, *rounding);
    if (rounding && area_edges) note_area(e, n, *rounding);
    const Rect region = area_edges ? area_cover(e.x, e.y, e.side, n) : pcss_square(e.x, e.y, e.side, n, nullptr);
    const double zmin =
        scan.min(structure == Structure::mip ? mip_square_cover(region, n) : covering_square(region, n));
    ++*refinements;
    // The plane's highest threshold over the square's texels: a linear function's, at a corner.
    double highest = threshold, magnitude = std::fabs(threshold);
    if ((gradient[0] != 0.0 || gradient[1] != 0.0) && region.width > 0 && region.height > 0) {
      double rise = 0.0;
      const double first[2] = {region.x + 0.5 - e.x, region.y + 0.5 - e.y};
      const double last[2] = {region.x + region.width - 0.5 - e.x, region.y + region.height - 0.5 - e.y};
      for (int a = 0; a < 2; ++a) {
        rise += std::max(gradient[a] * first[a], gradient[a] * last[a]);
        magnitude += std::fabs(gradient[a]) * (std::fabs(first[a]) + std::fabs(last[a]) + 2.0 * std::fabs(a ? e.y : e.x));
      }
      highest = std::min(threshold, threshold + rise);
    }
    if (rounding && (bias != 0.0 || highest != threshold) && std::isfinite(zmin) && std::isfinite(highest) &&
        std::fabs(zmin - highest) <= rounding->relative * magnitude)
      rounding->ambiguous = true;  // float rounds d - bias, and the plane's range (widened by its rounding)
    if (!(zmin < highest)) {
      e.side = kRegionLit;
      return e;
    }
    const double side = light.blocker_window_texels(d, zmin);
    if (rounding && side != e.side && std::fabs(side - e.side) <= rounding->relative * std::max(side, e.side))
      rounding->ambiguous = true;  // shrinks or stops, by a float's rounding
    if (!(side < e.side)) break;
    e.side = side;
  }
  return e;
}

RegionEntry filter_entry(const LightModel& light, const RegionEntry& search, double blocker_mean, bool has_blocker,
                         double filter_scale) {
  RegionEntry e{search.depth, search.x, search.y, kRegionLit};
  if (search.lit() || !has_blocker) return e;
  const double side = filter_scale * light.penumbra_texels(search.depth, blocker_mean);
  e.side = (side >= 0.0 && std::isfinite(side)) ? side : 0.0;  // degenerate: one texel, a hard shadow
  return e;
}

bool shadowing_blocker(const DepthScan& scan, const LightModel& light, const RegionReceiver& receiver, double bias,
                       Rounding* rounding) {
  const double d = receiver.depth;
  if (receiver.valid == 0.0f || std::isnan(d)) return false;
  const int n = scan.size();
  const double threshold = d - bias, rel = rounding ? rounding->relative : 0.0;
  const double u = std::isnan(receiver.u) ? 0.0 : receiver.u, v = std::isnan(receiver.v) ? 0.0 : receiver.v;
  const Rect search = pcss_square(u, v, light.search_width_texels(d), n, nullptr);
  // Texel i lies in the m texels nearest c along an axis (pcss_square, the texel being inside the map).
  const auto inside = [](double c, double m, int i) {
    const double first = std::floor(c - 0.5 * m + 0.5);
    return first <= i && i < first + m;
  };
  bool uncertain = false;
  for (int y = search.y; y < search.y + search.height; ++y)
    for (int x = search.x; x < search.x + search.width; ++x) {
      const double z = scan.depths().at(x, y);
      const bool near_threshold = bias != 0.0 && std::isfinite(z) && std::isfinite(threshold) &&
                                  std::fabs(z - threshold) <= rel * std::fabs(threshold);
      if (!(z < threshold) && !near_threshold) continue;
      // The square of the width a blocker at z needs, and its variants within float
      // rounding of that width and of the square's origin: in all of them, or in some.
      const double w = light.blocker_window_texels(d, z);
      const auto side = [&](double s) { return std::clamp(std::round(s), 1.0, 4.0 * n); };
      // Outside the widest variant's reach (its side, its origin's rounding, a texel to spare): in
      // none of them. Only a shortcut: what follows decides the same for such a texel.
      const double reach = 0.5 * side(w * (1.0 + rel)) + rel * (std::fabs(u) + std::fabs(v) + 4.0 * n + 1.0) + 2.0;
      if (std::fabs(x + 0.5 - u) > reach || std::fabs(y + 0.5 - v) > reach) continue;
      bool all = true, some = false;
      for (const double m : {side(w), side(w * (1.0 - rel)), side(w * (1.0 + rel))}) {
        const double du = rel * (std::fabs(u) + m + 1.0), dv = rel * (std::fabs(v) + m + 1.0);
        bool all_x = true, some_x = false, all_y = true, some_y = false;
        for (const double o : {0.0, -1.0, 1.0}) {
          const bool ix = inside(u + o * du, m, x), iy = inside(v + o * dv, m, y);
          all_x = all_x && ix, some_x = some_x || ix, all_y = all_y && iy, some_y = some_y || iy;
        }
        all = all && all_x && all_y, some = some || (some_x && some_y);
      }
      if (all && !near_threshold && z < threshold) return true;
      if (some) uncertain = true;
    }
  if (uncertain && rounding) rounding->ambiguous = true;
  return false;
}

}  // namespace pn
