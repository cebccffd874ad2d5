#include "reference/cascades_reference.h"

#include <algorithm>
#include <cmath>

namespace pn {

double practical_split_reference(double lambda, double near, double far, int i, int count) {
  const double t = static_cast<double>(i) / count;
  return lambda * near * std::pow(far / near, t) + (1.0 - lambda) * (near + (far - near) * t);
}

double adaptive_lambda_reference(double near, double far) {
  return 0.6 + 0.4 * std::clamp(std::log10(far / near) - 2.0, 0.0, 1.0);
}

double enlargement_reference(double k, int i) { return 1.0 + (std::max(k, 1.0) - 1.0) / std::pow(2.0, i - 1); }

std::vector<double> hybrid_splits_reference(double lambda, double near, double far, int count, double k, double gap) {
  std::vector<double> enlarged(static_cast<size_t>(count) + 1);
  for (int i = 1; i < count; ++i)
    enlarged[static_cast<size_t>(i)] =
        near + (practical_split_reference(lambda, near, far, i, count) - near) * enlargement_reference(k, i);
  enlarged[static_cast<size_t>(count)] = far;
  std::vector<double> out{near};
  for (int i = 1; i <= count; ++i) {
    double reach = INFINITY;
    for (int j = i; j <= count; ++j)
      reach = std::min(reach, std::pow(1.0 - gap, j - i) * (enlarged[static_cast<size_t>(j)] - near));
    out.push_back(near + reach);
  }
  return out;
}

CascadeChoiceReference cascade_choice_reference(double z, double near, const std::vector<double>& split_far,
                                                double band, bool fade_last) {
  const int m = static_cast<int>(split_far.size());
  if (std::isnan(z) || z >= split_far.back()) return {m, m, 0.0};
  int index = 0;
  while (z >= split_far[static_cast<size_t>(index)]) ++index;
  const double end = split_far[static_cast<size_t>(index)];
  const double start = index == 0 ? near : split_far[static_cast<size_t>(index - 1)];
  const double band_start = end - band * (end - start);
  double weight = z > band_start ? (z - band_start) / (end - band_start) : 0.0;
  if (index == m - 1 && !fade_last) weight = 0.0;
  return {index, index + 1, weight};
}

double farthest_corner_distance(double a, double b, double tan_x, double tan_y, double centre) {
  double farthest = 0;
  for (double z : {a, b}) {
    const double radial2 = z * z * (tan_x * tan_x + tan_y * tan_y);  // the same for all four corners at z
    farthest = std::max(farthest, std::sqrt(radial2 + (z - centre) * (z - centre)));
  }
  return farthest;
}

SphereReference slice_sphere_reference(double a, double b, double tan_x, double tan_y) {
  double lo = a, hi = b + (b - a) + b * (tan_x * tan_x + tan_y * tan_y);
  for (int step = 0; step < 300; ++step) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (farthest_corner_distance(a, b, tan_x, tan_y, m1) < farthest_corner_distance(a, b, tan_x, tan_y, m2)) hi = m2;
    else lo = m1;
  }
  const double centre = 0.5 * (lo + hi);
  return {centre, farthest_corner_distance(a, b, tan_x, tan_y, centre)};
}

}  // namespace pn
