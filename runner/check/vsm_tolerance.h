// The float error bounds of vsm.glsl's steps (the vsm check derives them: its header), for the
// checks that hold the module's values to the definition in double (vsm, exports).
#pragma once

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>

#include "core/image.h"
#include "modules/vsm_face.h"

namespace pn::vsm_tolerance {

inline constexpr double kU = FLT_EPSILON / 2.0;

inline double largest_exponent(const VsmParams& p) {
  if (p.kind == VsmKind::vsm) return 0.0;
  return p.kind == VsmKind::evsm2 ? p.positive_exponent : std::max(p.positive_exponent, p.negative_exponent);
}

// The relative error of EVSM's warp exp(c x) in float.
inline double warp_error(const VsmParams& p) { return 2.0 * kU * (11.0 * largest_exponent(p) + 6.0); }

// Chebyshev's bound on the blurred moments, and after the bleeding reduction (absolute).
inline double chebyshev_tolerance(const VsmParams& p) {
  const double mv = p.min_variance;
  double bound = 2.0 * ((kU / mv + 7.0 * kU) / 4.0 + 6.0 * kU);
  if (p.kind != VsmKind::vsm) bound += 2.0 * warp_error(p) * (0.65 / std::sqrt(mv) + 0.5);
  return bound;
}

inline double reduced_tolerance(const VsmParams& p) {
  return chebyshev_tolerance(p) / (1.0 - p.bleeding_reduction) + 8.0 * kU;
}

// A texel's moments (the image's channels) as the reference takes them.
inline std::array<double, 4> moments_at(const Image& m, int x, int y) {
  std::array<double, 4> out{};
  for (int c = 0; c < m.channels; ++c) out[static_cast<size_t>(c)] = m.at(x, y, c);
  return out;
}

}  // namespace pn::vsm_tolerance
