#include "reference/vogel_pcss_reference.h"

#include <algorithm>
#include <cmath>

#include "modules/vogel_pcss.h"

namespace pn {

VogelPcssPosition vogel_pcss_position(const VogelPcssQuery& q, int k, int n) {
  const double golden = 0.5 * (3.0 - std::sqrt(5.0));
  const double rho = std::sqrt((k + 0.5) / n);
  const double turns = k * golden + q.turn;
  const double theta = 2.0 * M_PI * (turns - std::floor(turns) - 0.5);
  const double radius = 0.5 * q.diameter * rho;
  return {q.centre_x + radius * std::cos(theta), q.centre_y + radius * std::sin(theta)};
}

VogelPcssBounds vogel_pcss_bounds(const Image& depth, const VogelPcssQuery& q,
                                  const std::function<double(int k, int n)>& position_error, double tie) {
  const int n = std::clamp(q.count, 0, kVogelMaxSamples);
  const double t = q.receiver_depth - q.bias;
  VogelPcssBounds b;
  for (int k = 0; k < n; ++k) {
    ++b.samples;
    const VogelPcssPosition p = vogel_pcss_position(q, k, n);
    const double e = position_error(k, n);
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
          const double along_x = q.gradient_x * (x + 0.5 - q.centre_x), along_y = q.gradient_y * (y + 0.5 - q.centre_y);
          const double threshold = t + along_x + along_y;
          const double band = tie > 0.0 && std::isfinite(t) ? tie * (std::fabs(t) + std::fabs(along_x) + std::fabs(along_y)) : 0.0;
          const bool finite = std::isfinite(d);
          if (finite && d < threshold + band) can_occlude = true, least = std::min(least, d), most = std::max(most, d);
          if (!(finite && d < threshold - band)) can_miss = true;
        }
    if (can_occlude && (can_miss || least != most)) ++b.ambiguous;
    if (can_occlude && !can_miss) ++b.occluders_lo, b.depth_sum_lo += least;
    if (can_occlude) ++b.occluders_hi, b.depth_sum_hi += most;
  }
  return b;
}

double interleaved_gradient_noise(double x, double y) {
  const double inner = PN_IGN_X * x + PN_IGN_Y * y;
  const double outer = PN_IGN_Z * (inner - std::floor(inner));
  return outer - std::floor(outer);
}

}  // namespace pn
