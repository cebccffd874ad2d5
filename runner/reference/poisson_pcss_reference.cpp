#include "reference/poisson_pcss_reference.h"

#include <algorithm>
#include <cmath>

namespace pn {

PoissonPcssPosition poisson_pcss_position(const PoissonPcssQuery& q, const Sample& offset) {
  const double ox = offset.x, oy = offset.y;
  const double rx = q.rotation_x * ox - q.rotation_y * oy;
  const double ry = q.rotation_y * ox + q.rotation_x * oy;
  const double radius = 0.5 * q.diameter;
  return {q.centre_x + radius * rx, q.centre_y + radius * ry};
}

PoissonPcssSums poisson_pcss_reference(const Image& depth, const std::vector<Sample>& points,
                                       const PoissonPcssQuery& query) {
  const int count = std::clamp(query.count, 0, static_cast<int>(points.size()));
  const double t = query.receiver_depth - query.bias;
  PoissonPcssSums s;
  for (int k = 0; k < count; ++k) {
    ++s.samples;
    const PoissonPcssPosition p = poisson_pcss_position(query, points[static_cast<size_t>(k)]);
    // Inside the map: 0 <= p < N on both axes (false for NaN and ±Inf).
    if (!(p.x >= 0.0 && p.y >= 0.0 && p.x < depth.width && p.y < depth.height)) continue;
    const double d = depth.at(static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)));
    if (std::isfinite(d) && d < t) ++s.occluders, s.depth_sum += d;
  }
  return s;
}

}  // namespace pn
