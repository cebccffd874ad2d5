#include "check/disk_layouts.h"

#include <algorithm>
#include <cmath>

#include "modules/vogel_pcss_face.h"
#include "vogel_pcss.h"

namespace pn {

double vogel_position_error(const VogelPcssQuery& q, int k) {
  const double r = 0.5 * q.diameter;
  const double angle = 2.0 * M_PI * 4.0 * kFloatUnit * (0.382 * k + 2.0);
  const double centre = std::max(std::fabs(q.centre_x), std::fabs(q.centre_y));
  return r * (kTrigError + angle + 8.0 * kFloatUnit) + 4.0 * kFloatUnit * (centre + r + 1.0);
}

double vogel_noise_bound(double x, double y) {
  return 53.0 * kFloatUnit * (3.1 * (PN_IGN_X * std::fabs(x) + PN_IGN_Y * std::fabs(y)) + 2.0);
}

DiskLayout poisson_layout(const std::vector<Sample>& disk, int count, double rotation_cos, double rotation_sin,
                          double trig) {
  return [&disk, count, rotation_cos, rotation_sin, trig](double cx, double cy, double diameter, double diameter_error) {
    std::vector<DiskSamplePosition> out;
    const double r = 0.5 * diameter;
    const double error =
        4.0 * kFloatUnit * (std::max(std::fabs(cx), std::fabs(cy)) + r + 1.0) + 2.0 * trig * r + 0.5 * diameter_error;
    for (int k = 0; k < std::min<int>(count, static_cast<int>(disk.size())); ++k) {
      const double ox = disk[static_cast<std::size_t>(k)].x, oy = disk[static_cast<std::size_t>(k)].y;
      out.push_back({cx + r * (rotation_cos * ox - rotation_sin * oy), cy + r * (rotation_sin * ox + rotation_cos * oy),
                     error});
    }
    return out;
  };
}

DiskLayout vogel_layout(int count, int px, int py) {
  return [count, px, py](double cx, double cy, double diameter, double diameter_error) {
    VogelPcssQuery q;
    q.centre_x = cx, q.centre_y = cy, q.diameter = diameter, q.count = count;
    q.turn = interleaved_gradient_noise(px + 0.5, py + 0.5);
    // The turn's own float error moves every sample along its circle.
    const double turn_error = 2.0 * M_PI * vogel_noise_bound(px + 0.5, py + 0.5) * 0.5 * diameter;
    const int n = std::clamp(count, 0, kVogelMaxSamples);
    std::vector<DiskSamplePosition> out;
    for (int k = 0; k < n; ++k) {
      const VogelPcssPosition p = vogel_pcss_position(q, k, n);
      out.push_back({p.x, p.y, vogel_position_error(q, k) + turn_error + 0.5 * diameter_error});
    }
    return out;
  };
}

}  // namespace pn
