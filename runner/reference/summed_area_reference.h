// CPU reference for glsl/summed_area.glsl, written from its definition and
// never through a summed-area table: every rectangle is clipped to the map and
// its texels are added up one by one — the raw depths in double, and the
// fixed-point values q(d) = roundEven(clamp(d, ±2^(52-F)) · 2^F) in 64-bit
// integers (modulo 2^64, as the table's words wrap). Non-finite texels (NaN,
// ±Inf) are covered but excluded from the sums and the finite count.
#pragma once

#include <cstdint>
#include <vector>

#include <summed_area.h>  // glsl/summed_area.h: PN_SUMMED_AREA_*, shared with the shader

#include "core/image.h"

namespace pn {

inline constexpr int kSummedAreaFractionBits = PN_SUMMED_AREA_FRACTION_BITS;
inline constexpr int kSummedAreaMagnitudeBits = PN_SUMMED_AREA_MAGNITUDE_BITS;
inline constexpr int kSummedAreaMaxSide = PN_SUMMED_AREA_MAX_SIDE;
inline constexpr int kSummedAreaMomentBits = PN_SUMMED_AREA_MOMENT_BITS;
inline constexpr int kSummedAreaMaxMomentBits = PN_SUMMED_AREA_MAX_MOMENT_BITS;

struct SummedAreaRect {
  int x = 0, y = 0;           // origin, texels (may lie outside the map)
  int width = 0, height = 0;  // <= 0: empty
};

// The covered part of `rect` on a width × height map: [x0, x1) × [y0, y1).
struct SummedAreaCover {
  long x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  long texels() const { return (x1 - x0) * (y1 - y0); }
};
SummedAreaCover summed_area_cover(const SummedAreaRect& rect, int map_width, int map_height);

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

  SummedAreaSums sums(const SummedAreaRect& rect) const;
  int fraction_bits() const { return fraction_bits_; }

 private:
  int width_ = 0, height_ = 0, fraction_bits_ = 0;
  std::vector<double> depth_;            // 0 where not finite
  std::vector<std::int64_t> fixed_;      // 0 where not finite
  std::vector<double> quantisation_;     // per texel: its bound on |q·2^-F − d|
  std::vector<unsigned char> finite_;
};

// One rectangle of `depth`, summed directly (a SummedAreaReference made for it).
SummedAreaSums summed_area_reference(const Image& depth, const SummedAreaRect& rect,
                                     int fraction_bits = kSummedAreaFractionBits);

// The bound on |float rectangle sum from the module − Σ d| for these sums: the
// quantisation bound E plus the conversion's 2u + u² (u = 2⁻²⁴) of |Σ q·2^-F|
// ≤ |Σ d| + E, plus u of |Σ d| for the reference's rounding to float, plus
// the double sum's own rounding (count · 2⁻⁵³ · Σ|d|).
double summed_area_sum_bound(const SummedAreaSums& s);
// The same for the mean: the sum's bound over the count, the division's
// rounding and the reference's rounding to float; 0 without finite texels.
double summed_area_mean_bound(const SummedAreaSums& s);

}  // namespace pn
