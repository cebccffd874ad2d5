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

SummedAreaCover summed_area_cover(const Rect& rect, int map_width, int map_height) {
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

SummedAreaSums SummedAreaReference::sums(const Rect& rect) const {
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

SummedAreaSums summed_area_reference(const Image& depth, const Rect& rect, int fraction_bits) {
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

// ---- Moments tables ----------------------------------------------------------

namespace pn {
namespace {

constexpr double kWiden = 1.0 + 0x1p-20;  // covers the u² terms each first-order bound leaves out

__extension__ typedef unsigned __int128 Uint128;  // GCC's and Clang's; the true sums Σq, Σq²

void check_moment_bits(int moment_bits) {
  if (moment_bits < 0 || moment_bits > kSummedAreaMaxMomentBits)
    throw Error("summed-area moment bits " + std::to_string(moment_bits) + ": expected 0 to " +
                std::to_string(kSummedAreaMaxMomentBits));
}

void check_range(const MomentsDepthRange& r) {
  if (!std::isfinite(r.near_depth) || !std::isfinite(r.far_depth) || r.near_depth < 0.0 ||
      !(r.far_depth > r.near_depth) || !std::isfinite(r.offset) || !std::isfinite(r.scale) || !(r.scale > 0.0f))
    throw Error("moments depth range [" + std::to_string(r.near_depth) + ", " + std::to_string(r.far_depth) +
                "] (offset " + std::to_string(r.offset) + ", scale " + std::to_string(r.scale) +
                "): expected finite 0 <= near < far and a finite scale > 0");
}

// γ_k = k u / (1 − k u): the relative error of k roundings in a row (k <= 0: none).
double gamma(long k) { return k <= 0 ? 0.0 : static_cast<double>(k) * kU / (1.0 - static_cast<double>(k) * kU); }

// The long double sums' own rounding, in units of x (every |x| <= 1): generous for n terms.
double reference_rounding(long n) { return static_cast<double>(n + 2) * 0x1p-62; }

}  // namespace

float summed_area_unit_depth(float depth, float offset, float scale) {
  if (!std::isfinite(depth)) return 1.0f;
  const float t = depth - offset;  // each operation rounded to float, as in GLSL
  const float x = t * scale;
  return std::min(std::max(x, 0.0f), 1.0f);
}

double summed_area_true_unit_depth(double depth, double near_depth, double far_depth) {
  if (!std::isfinite(depth)) return 1.0;
  return std::clamp((depth - near_depth) / (far_depth - near_depth), 0.0, 1.0);
}

std::uint32_t summed_area_moment_q(float x, int moment_bits) {
  check_moment_bits(moment_bits);
  // x · 2^B is exact; nearbyint rounds half to even in the default rounding mode.
  return static_cast<std::uint32_t>(std::nearbyint(std::ldexp(static_cast<double>(x), moment_bits)));
}

double summed_area_unit_depth_bound(const MomentsDepthRange& r) {
  check_range(r);
  const double width = r.far_depth - r.near_depth;
  // The scale's relative error (its product with the width rounds once in double: 2^-52 covers it).
  const double delta_s = std::fabs(static_cast<double>(r.scale) * width - 1.0) + 0x1p-52;
  const double delta_o = std::fabs(r.near_depth - static_cast<double>(r.offset)) / width;
  // The subtraction's relative u and the scale's δ_s scale |y| <= 1 + δ_o; the product rounds a
  // value below 1 by at most half its ulp, u/2 (subnormals included; values from 1 on clamp to 1).
  const double g = (1.0 + kU) * (1.0 + delta_s) - 1.0;
  return (g * (1.0 + delta_o) + delta_o + kU / 2.0) * kWiden;
}

double summed_area_moment_texel_bound(const MomentsDepthRange& range, int moment_bits) {
  check_moment_bits(moment_bits);
  return std::ldexp(1.0, -(moment_bits + 1)) + summed_area_unit_depth_bound(range);
}

SummedAreaMomentsReference::SummedAreaMomentsReference(const Image& depth, const MomentsDepthRange& range,
                                                       int moment_bits)
    : width_(depth.width), height_(depth.height), moment_bits_(moment_bits), range_(range) {
  check_moment_bits(moment_bits);
  unit_bound_ = summed_area_unit_depth_bound(range);
  texel_bound_ = summed_area_moment_texel_bound(range, moment_bits);
  const size_t w = static_cast<size_t>(width_), h = static_cast<size_t>(height_);
  x_.assign(w * h, 0.0);
  q_.assign(w * h, 0);
  prefix1_.assign((w + 1) * (h + 1), 0.0);
  prefix2_.assign((w + 1) * (h + 1), 0.0);
  const double step = std::ldexp(1.0, -moment_bits);
  for (size_t y = 0; y < h; ++y) {
    double row1 = 0.0, row2 = 0.0;  // prefixes of |v| and w along the row (a bound's input, in double)
    for (size_t x = 0; x < w; ++x) {
      const size_t i = y * w + x;
      const float d = depth.at(static_cast<int>(x), static_cast<int>(y));
      const float unit = summed_area_unit_depth(d, range.offset, range.scale);
      const float v = unit - 0.5f;  // pnSummedAreaFloatMomentsTexel
      const float vv = v * v;
      x_[i] = summed_area_true_unit_depth(d, range.near_depth, range.far_depth);
      q_[i] = summed_area_moment_q(unit, moment_bits);
      worst_unit_error_ = std::max(worst_unit_error_, std::fabs(static_cast<double>(unit) - x_[i]));
      worst_texel_error_ = std::max(worst_texel_error_, std::fabs(static_cast<double>(q_[i]) * step - x_[i]));
      row1 += std::fabs(static_cast<double>(v));
      row2 += static_cast<double>(vv);
      prefix1_[(y + 1) * (w + 1) + x + 1] = prefix1_[y * (w + 1) + x + 1] + row1;
      prefix2_[(y + 1) * (w + 1) + x + 1] = prefix2_[y * (w + 1) + x + 1] + row2;
    }
  }
}

MomentsSums SummedAreaMomentsReference::sums(const Rect& rect) const {
  const SummedAreaCover c = summed_area_cover(rect, width_, height_);
  MomentsSums s;
  s.texels = c.texels();
  if (s.texels == 0) return s;
  const size_t w = static_cast<size_t>(width_);
  Uint128 s1 = 0, s2 = 0;  // the true integer sums (< 2^28 · 2^36 for any map the module takes)
  long double sum_x = 0.0L;
  for (long y = c.y0; y < c.y1; ++y)
    for (long x = c.x0; x < c.x1; ++x) {
      const size_t i = static_cast<size_t>(y) * w + static_cast<size_t>(x);
      const std::uint64_t q = q_[i];
      s1 += q, s2 += q * q;
      sum_x += x_[i];
    }
  const long double n = static_cast<long double>(s.texels);
  const long double mean = sum_x / n;
  long double deviation = 0.0L, square = 0.0L;  // second pass, with the correction term of the first's rounding
  for (long y = c.y0; y < c.y1; ++y)
    for (long x = c.x0; x < c.x1; ++x) {
      const long double e = x_[static_cast<size_t>(y) * w + static_cast<size_t>(x)] - mean;
      deviation += e, square += e * e;
    }
  s.sum_q = static_cast<std::uint64_t>(s1);
  s.sum_q2 = static_cast<std::uint64_t>(s2);
  s.mean = static_cast<double>(mean + deviation / n);
  s.variance = static_cast<double>(std::max((square - deviation * deviation / n) / n, 0.0L));
  const long double step = std::ldexp(1.0L, -moment_bits_);
  s.quantised_mean = static_cast<double>(static_cast<long double>(s1) / n * step);
  // n Σq² − (Σq)² = n² var(q) >= 0, exact in 128 bits (< 2^28 · 2^64 + ...: below 2^100 here).
  const Uint128 numerator = static_cast<Uint128>(s.texels) * s2 - s1 * s1;
  s.quantised_variance = static_cast<double>(static_cast<long double>(numerator) / n / n * step * step);
  // The float table: its four corners' prefix bounds.
  const auto corner = [&](long cx, long cy) {
    const size_t k = static_cast<size_t>(cy) * (w + 1) + static_cast<size_t>(cx);
    const double g = gamma(cx + cy - 2);
    s.float_prefix_error1 += g * prefix1_[k], s.float_prefix_error2 += g * prefix2_[k];
    s.float_corner_abs1 += prefix1_[k], s.float_corner_abs2 += prefix2_[k];
  };
  corner(c.x1, c.y1), corner(c.x1, c.y0), corner(c.x0, c.y1), corner(c.x0, c.y0);
  // A was summed in double (relative error far below 2^-30 at these sizes): widened.
  for (double* v : {&s.float_prefix_error1, &s.float_prefix_error2, &s.float_corner_abs1, &s.float_corner_abs2})
    *v *= 1.0 + 0x1p-30;
  return s;
}

MomentsBounds SummedAreaMomentsReference::fixed_arithmetic_bound(const MomentsSums& s) const {
  if (s.texels == 0) return {};
  const double step = std::ldexp(1.0, -moment_bits_);
  const double rho = 0.5 + (7.0 * kU + 12.0 * kU * kU) * std::ldexp(1.0, moment_bits_);  // |mean of q − c|
  MomentsBounds b;
  b.mean = (kU * s.quantised_mean + 6.0 * kU * rho * step) * kWiden + 0x1p-52 * s.quantised_mean;
  b.variance = (8.0 * kU * s.quantised_variance + 20.0 * kU * rho * rho * step * step) * kWiden +
               0x1p-52 * s.quantised_variance;
  return b;
}

MomentsBounds SummedAreaMomentsReference::fixed_bound(const MomentsSums& s) const {
  if (s.texels == 0) return {};
  const MomentsBounds a = fixed_arithmetic_bound(s);
  const double e = texel_bound_, sigma = std::sqrt(s.variance), r = reference_rounding(s.texels);
  return {a.mean + e + r, a.variance + (2.0 * sigma * e + e * e) * kWiden + r};
}

MomentsBounds SummedAreaMomentsReference::float_bound(const MomentsSums& s) const {
  if (s.texels == 0) return {};
  const double n = static_cast<double>(s.texels);
  const double eps_v = unit_bound_ + kU / 2.0, eps_w = eps_v + kU / 4.0;
  const double corner = 2.0 * kU + kU * kU;
  const double e1 = n * eps_v + s.float_prefix_error1 + corner * (s.float_corner_abs1 + s.float_prefix_error1);
  const double e2 = n * eps_w + s.float_prefix_error2 + corner * (s.float_corner_abs2 + s.float_prefix_error2);
  const double mu1 = std::fabs(s.mean - 0.5), mu2 = s.variance + mu1 * mu1;  // E[v], E[v²] of the true x
  const double f1 = e1 / n + 5.0 * kU * (mu1 + e1 / n);                          // E[v]: the division's 2.5 ulp
  const double f2 = e2 / n + 5.0 * kU * (mu2 + e2 / n);
  const double g = f1 * (2.0 * mu1 + f1) + kU * (mu1 + f1) * (mu1 + f1);           // E[v]², its product rounded
  const double r = reference_rounding(s.texels);
  return {(f1 + kU * (s.mean + f1)) * kWiden + r, (f2 + g + kU * (s.variance + f2 + g)) * kWiden + r};
}

}  // namespace pn
