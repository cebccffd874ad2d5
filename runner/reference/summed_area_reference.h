// CPU reference for glsl/summed_area.glsl, written from its definition and
// never through a summed-area table: every rectangle is clipped to the map and
// its texels are added up one by one — the raw depths in double, and the
// fixed-point values q(d) = roundEven(clamp(d, ±2^(52-F)) · 2^F) in 64-bit
// integers (modulo 2^64, as the table's words wrap). Non-finite texels (NaN,
// ±Inf) are covered but excluded from the sums and the finite count.
#pragma once

#include <cstdint>
#include <vector>

#include "core/image.h"
#include "core/texel_rect.h"
#include "modules/summed_area_face.h"

namespace pn {

// The covered part of `rect` on a width × height map: [x0, x1) × [y0, y1).
struct SummedAreaCover {
  long x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  long texels() const { return (x1 - x0) * (y1 - y0); }
};
SummedAreaCover summed_area_cover(const Rect& rect, int map_width, int map_height);

// q(d) for a finite depth: round half to even of the clamped depth times 2^F. Throws Error unless
// 0 <= fraction_bits <= kSummedAreaMagnitudeBits; `depth` must be finite.
std::int64_t summed_area_fixed(double depth, int fraction_bits = kSummedAreaFractionBits);

// The float value of a 64-bit two's complement fixed-point sum: q · 2^-F, in double.
double summed_area_fixed_value(std::uint64_t fixed_sum, int fraction_bits = kSummedAreaFractionBits);

struct SummedAreaSums {
  double sum = 0.0;               // Σ d over the finite texels, in double (naive: within count·2^-53·Σ|d|)
  double magnitude = 0.0;         // Σ |d| over the finite texels
  std::uint64_t fixed_sum = 0;    // Σ q(d) modulo 2^64 (two's complement)
  double fixed_magnitude = 0.0;   // Σ |q(d)|: the fixed sum is the true one (read as signed) when < 2^63
  long count = 0;                 // finite texels
  long texels = 0;                // texels covered
  double quantisation_bound = 0;  // bound on |Σ q·2^-F − Σ d|: 2^-(F+1) per finite |d| < 2^(23-F), plus any clamp

  // Whether the 64-bit sum is the exact one: |Σ q| < 2^63, with room for Σ|q|'s own rounding.
  bool fixed_sum_fits() const { return fixed_magnitude < 0x1p62; }
  double mean() const { return count > 0 ? sum / static_cast<double>(count) : 0.0; }
};

// A map's texels prepared once (finite flag, depth, q), then summed over any
// rectangle directly: O(area) per rectangle.
class SummedAreaReference {
 public:
  // `depth` is the raw single-channel map (NaN and ±Inf allowed).
  explicit SummedAreaReference(const Image& depth, int fraction_bits = kSummedAreaFractionBits);

  SummedAreaSums sums(const Rect& rect) const;
  int fraction_bits() const { return fraction_bits_; }

 private:
  int width_ = 0, height_ = 0, fraction_bits_ = 0;
  std::vector<double> depth_;            // 0 where not finite
  std::vector<std::int64_t> fixed_;      // 0 where not finite
  std::vector<double> quantisation_;     // per texel: its bound on |q·2^-F − d|
  std::vector<unsigned char> finite_;
};

// One rectangle of `depth`, summed directly (a SummedAreaReference made for it).
SummedAreaSums summed_area_reference(const Image& depth, const Rect& rect,
                                     int fraction_bits = kSummedAreaFractionBits);

// The bound on |float rectangle sum from the module − Σ d| for these sums: the
// quantisation bound E plus the conversion's 2u + u² (u = 2⁻²⁴) of |Σ q·2^-F|
// ≤ |Σ d| + E, plus u of |Σ d| for the reference's rounding to float, plus
// the double sum's own rounding (count · 2⁻⁵³ · Σ|d|).
double summed_area_sum_bound(const SummedAreaSums& s);
// The same for the mean: the sum's bound over the count, the division's
// rounding and the reference's rounding to float; 0 without finite texels.
double summed_area_mean_bound(const SummedAreaSums& s);

// ---- Moments tables (seed 004's summed-area variance shadow maps) ----------
//
// The first two moments of the unit depth x over a rectangle, by brute force
// per rectangle. Per texel the reference holds x as the GPU computes it in
// float (pnSummedAreaUnitDepth: a float subtraction and a float
// multiplication, each correctly rounded, then the clamp; non-finite depths
// give 1), its fixed-point value q = roundEven(x̃ · 2^B), and the true x =
// clamp((d − near) / (far − near), 0, 1) in double (1 for non-finite d). Per
// rectangle: Σq and Σq² modulo 2^64 (the table's words, exact), the exact
// mean and variance of q · 2^-B (from 128-bit integer sums) and the mean and
// variance of the true x (two passes in long double). Never a table.
//
// The bounds (u = 2^-24; derivation in docs/modules/summed_area.md, "Moments
// tables"; every one stated to first order and widened by 2^-20 of itself,
// more than the u² terms it leaves out):
//   per texel   |x̃ − x| <= ε_x = γ (1 + δ_o) + δ_o + u/2, γ = (1 + u)(1 + δ_s) − 1
//                 (the subtraction's relative u and the float scale's relative error δ_s on
//                 |(d − offset) / (far − near)| <= 1 + δ_o; the product, below 1, rounded by at
//                 most half an ulp, u/2; δ_o = |near − offset| / (far − near), 0 when near is a
//                 float. 1.5u + δ_s + δ_o to first order)
//               |q · 2^-B − x| <= e = 2^-(B+1) + ε_x
//   fixed table, GPU against the quantised values (arithmetic only; GLSL's
//     division within 2.5 ulp, i.e. relative 5u; conversions and + − × correctly rounded):
//               ρ = 1/2 + (7u + 12u²) 2^B bounds |mean of q − c|, c the rounded centre
//               mean:      u · mean_q + 6u · ρ · 2^-B
//               variance:  8u · var_q + 20u · ρ² · 2^-2B
//   fixed table, GPU against the true x: the above plus
//               mean:      e
//               variance:  2 σ e + e²          (σ the true x's standard deviation)
//   float table (texels v = x̃ − 1/2 and w = v², summed row then column in float):
//     per texel |v − (x − 1/2)| <= ε_v = ε_x + u/2, |w − (x − 1/2)²| <= ε_w = ε_v + u/4;
//     each prefix T(X, Y) is off by at most γ_{X+Y−2} · A(X, Y), A the prefix of |v| (of w);
//     the four-corner difference adds (2u + u²) Σ_c |T_c|; then the divisions by n (5u),
//     mean + 1/2 (u) and E[v²] − E[v]² (u of each term): float_moments_bound.
// Each bound adds (n + 2) · 2^-62 for the reference's own long double rounding.

// The depth range of a moments table: the true ends (x's definition) and the float offset and
// scale the GPU is given (pass_runners/summed_area_pass.h's unit_range rounds them once).
struct MomentsDepthRange {
  double near_depth = 0.0, far_depth = 1.0;
  float offset = 0.0f, scale = 1.0f;
};

// x̃ as pnSummedAreaUnitDepth computes it: (depth − offset) · scale in float, clamped; 1 if non-finite.
float summed_area_unit_depth(float depth, float offset, float scale);
// x by its definition, in double; 1 for a non-finite depth.
double summed_area_true_unit_depth(double depth, double near_depth, double far_depth);
// q = roundEven(x · 2^B) of x̃ in [0, 1]. Throws Error unless 0 <= B <= kSummedAreaMaxMomentBits.
std::uint32_t summed_area_moment_q(float x, int moment_bits = kSummedAreaMomentBits);
// ε_x and e above. Throw Error unless 0 <= near < far, both finite, and the scale and offset finite.
double summed_area_unit_depth_bound(const MomentsDepthRange& range);
double summed_area_moment_texel_bound(const MomentsDepthRange& range, int moment_bits = kSummedAreaMomentBits);

struct MomentsSums {
  std::uint64_t sum_q = 0, sum_q2 = 0;  // Σq and Σq² modulo 2^64: what the fixed table's four corners give
  long texels = 0;                      // texels covered (every texel counts: a non-finite one is x = 1)
  double mean = 0.0, variance = 0.0;    // of the true x (two passes in long double)
  double quantised_mean = 0.0, quantised_variance = 0.0;  // of q · 2^-B, exactly from Σq and Σq², rounded once
  // The float table's rounding at this rectangle's four corners (c = the table texels the query fetches):
  double float_prefix_error1 = 0.0, float_prefix_error2 = 0.0;  // Σ_c γ_{X+Y−2} A(c), for Σv and Σw
  double float_corner_abs1 = 0.0, float_corner_abs2 = 0.0;      // Σ_c A(c) (bounds Σ_c |T_c| / (1 + γ))
};

struct MomentsBounds {
  double mean = 0.0, variance = 0.0;  // absolute, in units of x
};

// Every texel of a map prepared once (x, x̃, q, v, w; the prefixes A of |v| and w — a bound's
// input, never a reference value), then each rectangle summed directly: O(area) per rectangle.
class SummedAreaMomentsReference {
 public:
  // Throws Error for a bad range or moment bits outside 0..kSummedAreaMaxMomentBits.
  SummedAreaMomentsReference(const Image& depth, const MomentsDepthRange& range,
                             int moment_bits = kSummedAreaMomentBits);

  MomentsSums sums(const Rect& rect) const;

  // GPU mean and variance from the fixed table against the exact moments of q · 2^-B: the
  // arithmetic of pnSummedAreaRectMoments alone.
  MomentsBounds fixed_arithmetic_bound(const MomentsSums& s) const;
  // The same against the true x: quantisation and x̃'s rounding added.
  MomentsBounds fixed_bound(const MomentsSums& s) const;
  // The float table's mean and variance (pnSummedAreaRectFloatMoments) against the true x.
  MomentsBounds float_bound(const MomentsSums& s) const;

  int moment_bits() const { return moment_bits_; }
  double texel_bound() const { return texel_bound_; }  // e
  double unit_depth_bound() const { return unit_bound_; }  // ε_x
  // max over the map of |q · 2^-B − x| and of |x̃ − x|: within e and ε_x (a self-check of the derivation).
  double worst_texel_error() const { return worst_texel_error_; }
  double worst_unit_depth_error() const { return worst_unit_error_; }

 private:
  int width_ = 0, height_ = 0, moment_bits_ = 0;
  MomentsDepthRange range_;
  double unit_bound_ = 0.0, texel_bound_ = 0.0;
  double worst_texel_error_ = 0.0, worst_unit_error_ = 0.0;
  std::vector<double> x_;            // the true x
  std::vector<std::uint32_t> q_;     // q of x̃
  std::vector<double> prefix1_, prefix2_;  // (width + 1) × (height + 1): A of |v| and of w, in double
};

}  // namespace pn
