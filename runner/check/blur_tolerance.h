// The blur's float rounding bound, for every check that compares a GPU blur
// with blur_reference: each of the two passes sums 2r+1 products whose weights
// come from float exp() and a float division, so the result is within a few
// ulps per tap of max |v|; 16 ulps per tap is a generous, stated bound.
#pragma once

#include <cfloat>

#include "check/compare.h"
#include "core/image.h"
#include "reference/blur_reference.h"

namespace pn {

inline Tolerance blur_tolerance(const BlurParams& params, const Image& source) {
  return Tolerance::absolute(16.0 * (2 * params.radius + 1) * FLT_EPSILON * largest_finite_magnitude(source, 1.0f));
}

}  // namespace pn
