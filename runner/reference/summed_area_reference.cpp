#include "reference/summed_area_reference.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace pn {
namespace {

constexpr double kU = 0x1p-24;  // float's unit roundoff

void check_fraction_bits(int fraction_bits) {
  if (fraction_bits < 0 || fraction_bits > kSummedAreaMagnitudeBits)
    throw Error("summed-area fraction bits " + std::to_string(fraction_bits) + ": expected 0 to " +
                std::to_string(kSummedAreaMagnitudeBits));
}

// The largest magnitude a depth keeps: 2^(52 - F).
double magnitude_limit(int fraction_bits) { return std::ldexp(1.0, kSummedAreaMagnitudeBits - fraction_bits); }

}  // namespace

SummedAreaCover summed_area_cover(const SummedAreaRect& rect, int map_width, int map_height) {
  // In 64-bit: no overflow whatever the rectangle.
  const auto axis = [](long origin, long size, long extent, long& lo, long& hi) {
    lo = std::clamp(origin, 0L, extent);
    hi = std::clamp(origin + std::max(size, 0L), lo, extent);
  };
  SummedAreaCover c;
  axis(rect.x, rect.width, map_width, c.x0, c.x1);
  axis(rect.y, rect.height, map_height, c.y0, c.y1);
  return c;
}

std::int64_t summed_area_fixed(double depth, int fraction_bits) {
  check_fraction_bits(fraction_bits);
  const double limit = magnitude_limit(fraction_bits);
  const double clamped = std::clamp(depth, -limit, limit);
  // ldexp is exact here (|clamped| · 2^F <= 2^52); nearbyint rounds half to even in the default mode.
  return static_cast<std::int64_t>(std::nearbyint(std::ldexp(clamped, fraction_bits)));
}

double summed_area_fixed_value(std::uint64_t fixed_sum, int fraction_bits) {
  // Two's complement read as signed, written without relying on a narrowing conversion.
  const bool negative = (fixed_sum >> 63) != 0;
  const std::uint64_t magnitude = negative ? ~fixed_sum + 1 : fixed_sum;
  const double value = std::ldexp(static_cast<double>(magnitude), -fraction_bits);
  return negative ? -value : value;
}

SummedAreaReference::SummedAreaReference(const Image& depth, int fraction_bits)
    : width_(depth.width), height_(depth.height), fraction_bits_(fraction_bits) {
  check_fraction_bits(fraction_bits);
  const double limit = magnitude_limit(fraction_bits);
  // Floats of magnitude >= 2^(23 - F) have no bits below 2^-F: q·2^-F is the depth itself.
  const double exact_from = std::ldexp(1.0, 23 - fraction_bits);
  const double half_step = std::ldexp(1.0, -(fraction_bits + 1));
  const size_t n = static_cast<size_t>(width_) * static_cast<size_t>(height_);
  depth_.assign(n, 0.0);
  fixed_.assign(n, 0);
  quantisation_.assign(n, 0.0);
  finite_.assign(n, 0);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const double d = depth.at(x, y);
      if (!std::isfinite(d)) continue;
      const size_t i = static_cast<size_t>(y) * static_cast<size_t>(width_) + static_cast<size_t>(x);
      finite_[i] = 1;
      depth_[i] = d;
      fixed_[i] = summed_area_fixed(d, fraction_bits);
      if (std::fabs(d) > limit) quantisation_[i] = std::fabs(d) - limit;
      else if (std::fabs(d) < exact_from) quantisation_[i] = half_step;
    }
}

SummedAreaSums SummedAreaReference::sums(const SummedAreaRect& rect) const {
  const SummedAreaCover c = summed_area_cover(rect, width_, height_);
  SummedAreaSums s;
  s.texels = c.texels();
  // Non-finite texels hold 0 in every array: added without a branch, they change nothing.
  for (long y = c.y0; y < c.y1; ++y) {
    const size_t row = static_cast<size_t>(y) * static_cast<size_t>(width_);
    for (long x = c.x0; x < c.x1; ++x) {
      const size_t i = row + static_cast<size_t>(x);
      s.count += finite_[i];
      s.sum += depth_[i];
      s.magnitude += std::fabs(depth_[i]);
      s.fixed_sum += static_cast<std::uint64_t>(fixed_[i]);  // unsigned: wraps modulo 2^64 by definition
      s.fixed_magnitude += std::fabs(static_cast<double>(fixed_[i]));
      s.quantisation_bound += quantisation_[i];
    }
  }
  return s;
}

SummedAreaSums summed_area_reference(const Image& depth, const SummedAreaRect& rect, int fraction_bits) {
  return SummedAreaReference(depth, fraction_bits).sums(rect);
}

double summed_area_sum_bound(const SummedAreaSums& s) {
  const double e = s.quantisation_bound, a = std::fabs(s.sum);
  const double reference = static_cast<double>(s.count) * 0x1p-53 * s.magnitude * (1.0 + 0x1p-40);
  return e + (2.0 * kU + kU * kU) * (a + e + reference) + kU * a + reference;
}

double summed_area_mean_bound(const SummedAreaSums& s) {
  if (s.count <= 0) return 0.0;
  const double c = static_cast<double>(s.count), b = summed_area_sum_bound(s), a = std::fabs(s.sum);
  return b / c + kU * (a + b) / c + kU * a / c;
}

}  // namespace pn
