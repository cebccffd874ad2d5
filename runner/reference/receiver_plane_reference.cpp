#include "reference/receiver_plane_reference.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "receiver_plane.h"

namespace pn {

Step3 receiver_plane_step(const Entry4& centre, const Entry4& minus, const Entry4& plus) {
  const bool has_minus = minus[3] != 0.0, has_plus = plus[3] != 0.0;
  const bool take_plus =
      has_plus && (!has_minus || std::fabs(plus[2] - centre[2]) <= std::fabs(centre[2] - minus[2]));
  if (take_plus) return {plus[0] - centre[0], plus[1] - centre[1], plus[2] - centre[2]};
  if (has_minus) return {centre[0] - minus[0], centre[1] - minus[1], centre[2] - minus[2]};
  return {0.0, 0.0, 0.0};
}

std::array<double, 2> receiver_plane_gradient(const Step3& a, const Step3& b, double max_slope) {
  // Rows: the steps' (du, dv); M g = (a.d, b.d).
  const glm::dmat2 m(a[0], b[0], a[1], b[1]);  // column-major: columns (a.u, b.u), (a.v, b.v)
  const double det = glm::determinant(m);
  if (!(std::fabs(det) > PN_RECEIVER_PLANE_MIN_SINE * std::hypot(a[0], a[1]) * std::hypot(b[0], b[1])))
    return {0.0, 0.0};
  const glm::dvec2 g = glm::inverse(m) * glm::dvec2(a[2], b[2]);
  const double slope = std::hypot(g.x, g.y);
  if (!std::isfinite(slope)) return {0.0, 0.0};
  const double scale = slope > max_slope ? max_slope / slope : 1.0;
  return {g.x * scale, g.y * scale};
}

std::array<double, 2> receiver_plane_range(const Step3& receiver, const std::array<double, 2>& g,
                                           const std::array<int, 2>& origin, const std::array<int, 2>& size) {
  double lo = INFINITY, hi = -INFINITY;
  for (int y = origin[1]; y < origin[1] + size[1]; ++y)
    for (int x = origin[0]; x < origin[0] + size[0]; ++x) {
      const double z = receiver[2] + g[0] * (x + 0.5 - receiver[0]) + g[1] * (y + 0.5 - receiver[1]);
      lo = std::min(lo, z), hi = std::max(hi, z);
    }
  return {lo, hi};
}

}  // namespace pn
