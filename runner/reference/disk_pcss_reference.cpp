#include "reference/disk_pcss_reference.h"

#include <algorithm>
#include <cmath>

#include "reference/receiver_plane_reference.h"

namespace pn {

DiskBounds disk_bounds(const Image& depth, const std::vector<DiskSamplePosition>& samples, double threshold,
                       double gradient_x, double gradient_y, double centre_x, double centre_y, double tie) {
  const double t = threshold;
  DiskBounds b;
  for (const DiskSamplePosition& p : samples) {
    ++b.samples;
    const double e = p.error;
    // Inside the map: 0 <= p < N on both axes (false for NaN and ±Inf). Every texel a position
    // within e of p reads, and "outside" where the square [p - e, p + e]² is not wholly inside.
    const bool inside = p.x - e >= 0.0 && p.y - e >= 0.0 && p.x + e < depth.width && p.y + e < depth.height;
    bool can_occlude = false, can_miss = !inside;
    double least = INFINITY, most = -INFINITY;
    const auto first = [e](double v) { return static_cast<long>(std::max(std::floor(v - e), 0.0)); };
    const auto last = [e](double v, int size) { return static_cast<long>(std::min(std::floor(v + e), size - 1.0)); };
    if (std::isfinite(p.x) && std::isfinite(p.y))
      for (long y = first(p.y); y <= last(p.y, depth.height); ++y)
        for (long x = first(p.x); x <= last(p.x, depth.width); ++x) {
          const double d = depth.at(static_cast<int>(x), static_cast<int>(y));
          const double along_x = gradient_x * (x + 0.5 - centre_x), along_y = gradient_y * (y + 0.5 - centre_y);
          const double at = receiver_plane_threshold(t, along_x + along_y);
          const double band = tie > 0.0 && std::isfinite(t) ? tie * (std::fabs(t) + std::fabs(along_x) + std::fabs(along_y)) : 0.0;
          const bool finite = std::isfinite(d);
          if (finite && d < at + band) can_occlude = true, least = std::min(least, d), most = std::max(most, d);
          if (!(finite && d < at - band)) can_miss = true;
        }
    if (can_occlude && (can_miss || least != most)) ++b.ambiguous;
    if (can_occlude && !can_miss) ++b.occluders_lo, b.depth_sum_lo += least;
    if (can_occlude) ++b.occluders_hi, b.depth_sum_hi += most;
  }
  return b;
}

namespace {

constexpr double kUnit = 1.0 / 16777216.0;  // u = 2^-24
constexpr double kTie = 8.0 * kUnit;        // a texel's comparison with its threshold, in float

}  // namespace

DiskPcssResult disk_pcss_reference(const Image& depth, const LightModel& light, const DiskPcssReceiver& r,
                                   double bias, double filter_scale, const DiskLayout& blocker_disk,
                                   const DiskLayout& filter_disk) {
  DiskPcssResult out;
  if (std::isnan(r.depth)) return out;  // no surface: lit
  const double t = r.depth - bias;
  // The search width, in float to a few ulps.
  const double search = light.search_width_texels(r.depth);
  const DiskBounds blockers = disk_bounds(depth, blocker_disk(r.u, r.v, search, 8.0 * kUnit * search), t,
                                          r.gradient_x, r.gradient_y, r.u, r.v, kTie);
  if (blockers.ambiguous > 0) return {true, 0.0, 1.0};
  if (blockers.occluders_hi == 0) return out;  // no blocker: lit
  // The mean is a float sum of n terms and a division: relative error <= (n + 2) u; the filter's
  // diameter moves by what that moves Eq. (1), plus its own few ulps.
  const double n = static_cast<double>(blockers.occluders_hi);
  const double mean = blockers.depth_sum_hi / n, spread = (n + 2.0) * kUnit * std::fabs(mean);
  const auto filter_side = [&](double z) {
    const double side = filter_scale * light.penumbra_texels(r.depth, z);
    return side >= 0.0 && std::isfinite(side) ? side : 0.0;
  };
  const double side = filter_side(mean);
  const double side_error = std::max(std::fabs(filter_side(mean - spread) - side), std::fabs(filter_side(mean + spread) - side)) +
                            16.0 * kUnit * side;
  const DiskBounds filtered = disk_bounds(depth, filter_disk(r.u, r.v, side, side_error), t, r.gradient_x,
                                          r.gradient_y, r.u, r.v, kTie);
  if (filtered.samples == 0) return out;  // no sample: nothing occludes, lit (the module's 0 / 0 = 0)
  const double samples = static_cast<double>(filtered.samples);
  out.visibility_lo = 1.0 - static_cast<double>(filtered.occluders_hi) / samples;
  out.visibility_hi = 1.0 - static_cast<double>(filtered.occluders_lo) / samples;
  return out;
}

}  // namespace pn
