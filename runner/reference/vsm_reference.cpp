#include "reference/vsm_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "core/format.h"

namespace pn {
namespace {

double clamped_exponent(float c) { return std::clamp(static_cast<double>(c), 0.0, kEvsmMaxExponent); }

}  // namespace

double evsm_warp_coordinate(double depth, const VsmParams& params) {
  if (!std::isfinite(depth)) return 1.0;
  const double x = (depth - params.near_depth) / (static_cast<double>(params.far_depth) - params.near_depth);
  return std::clamp(x, 0.0, 1.0);
}

std::array<double, 4> vsm_moments(float depth, const VsmParams& params) {
  if (params.kind == VsmKind::vsm) {
    const double d = std::isfinite(depth) ? depth : params.far_depth;
    return {d, d * d, 0.0, 0.0};
  }
  const double x = evsm_warp_coordinate(depth, params);
  const double positive = std::exp(clamped_exponent(params.positive_exponent) * x);
  const double negative = -std::exp(-clamped_exponent(params.negative_exponent) * x);
  if (params.kind == VsmKind::evsm2) return {positive, positive * positive, 0.0, 0.0};
  return {positive, positive * positive, negative, negative * negative};
}

Image vsm_moments_reference(const Image& depth, const VsmParams& params) {
  const int channels = vsm_moment_channels(params.kind);
  Image out(depth.width, depth.height, channels);
  for (int y = 0; y < depth.height; ++y)
    for (int x = 0; x < depth.width; ++x) {
      const std::array<double, 4> m = vsm_moments(depth.at(x, y), params);
      for (int c = 0; c < channels; ++c) out.at(x, y, c) = static_cast<float>(m[static_cast<size_t>(c)]);
    }
  return out;
}

Image vsm_window_moments_reference(const Image& depth, const VsmParams& params) {
  return blur_reference(vsm_moments_reference(depth, params), params.blur);
}

double floored_variance(double mean, double variance, double min_variance) {
  const double floor = std::max(std::max(min_variance, 0.0) * mean * mean, static_cast<double>(kVsmVarianceFloor));
  return std::max(variance, floor);
}

double chebyshev_bound_variance(double mean, double variance, double t, double min_variance) {
  if (!(t > mean)) return 1.0;
  const double v = floored_variance(mean, variance, min_variance);
  const double delta = t - mean;
  return v / (v + delta * delta);
}

double chebyshev_bound(double m1, double m2, double t, double min_variance) {
  return chebyshev_bound_variance(m1, m2 - m1 * m1, t, min_variance);
}

double reduce_bleeding(double p, double amount) {
  const double a = std::clamp(amount, 0.0, kVsmMaxBleedingReduction);
  return std::clamp((p - a) / (1.0 - a), 0.0, 1.0);
}

double vsm_bound(const std::array<double, 4>& m, float t, const VsmParams& params) {
  if (params.kind == VsmKind::vsm) return chebyshev_bound(m[0], m[1], t, params.min_variance);
  if (std::isnan(t)) return 1.0;
  const double x = evsm_warp_coordinate(t, params);
  const double positive = chebyshev_bound(m[0], m[1], std::exp(clamped_exponent(params.positive_exponent) * x),
                                          params.min_variance);
  if (params.kind == VsmKind::evsm2) return positive;
  const double negative = chebyshev_bound(m[2], m[3], -std::exp(-clamped_exponent(params.negative_exponent) * x),
                                          params.min_variance);
  return std::min(positive, negative);
}

DepthRange window_depth_range(const Image& depth, int x, int y, int radius) {
  const int n = std::min(depth.width, depth.height);
  const int side = std::clamp(2 * radius + 1, 1, n);
  const int x0 = std::clamp(x - radius, 0, depth.width - side), y0 = std::clamp(y - radius, 0, depth.height - side);
  DepthRange r{std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()};
  for (int j = y0; j < y0 + side; ++j)
    for (int i = x0; i < x0 + side; ++i) {
      const float d = depth.at(i, j);
      const float v = std::isfinite(d) ? d : std::numeric_limits<float>::infinity();
      r.min = std::min(r.min, v);
      r.max = std::max(r.max, v);
    }
  return r;
}

double depth_range_bound(const DepthRange& range, float t) {
  if (t <= range.min) return PN_VSM_BOUND_LIT;
  if (t > range.max) return PN_VSM_BOUND_SHADOWED;
  return PN_VSM_BOUND_NONE;
}

double vsm_visibility(double bound_code, double reduced) {
  return bound_code == PN_VSM_BOUND_NONE ? reduced : bound_code;
}

double gaussian_pcf_visibility(const Image& depth, int x, int y, float t, const BlurParams& blur) {
  const int r = blur.radius;
  const std::vector<double> w = normalised_gaussian(r, blur.sigma);
  double lit = 0.0;
  for (int j = -r; j <= r; ++j)
    for (int i = -r; i <= r; ++i) {
      const float d = depth.at(std::clamp(x + i, 0, depth.width - 1), std::clamp(y + j, 0, depth.height - 1));
      const bool occludes = std::isfinite(d) && d < t;
      if (!occludes) lit += w[static_cast<size_t>(i + r)] * w[static_cast<size_t>(j + r)];
    }
  return lit;
}

}  // namespace pn
