#include "reference/vogel_pcss_reference.h"

#include <algorithm>
#include <cmath>

#include "modules/vogel_pcss_face.h"
#include "reference/disk_pcss_reference.h"

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
  std::vector<DiskSamplePosition> samples;
  for (int k = 0; k < n; ++k) {
    const VogelPcssPosition p = vogel_pcss_position(q, k, n);
    samples.push_back({p.x, p.y, position_error(k, n)});
  }
  const DiskBounds b = disk_bounds(depth, samples, q.receiver_depth - q.bias, q.gradient_x, q.gradient_y, q.centre_x,
                                   q.centre_y, tie);
  return {b.occluders_lo, b.occluders_hi, b.depth_sum_lo, b.depth_sum_hi, b.samples, b.ambiguous};
}

double interleaved_gradient_noise(double x, double y) {
  const double inner = PN_IGN_X * x + PN_IGN_Y * y;
  const double outer = PN_IGN_Z * (inner - std::floor(inner));
  return outer - std::floor(outer);
}

}  // namespace pn
