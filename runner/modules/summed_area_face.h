// C++ face of glsl/summed_area.glsl: the fixed-point formats of the depth-sum
// and moments tables and the largest map they take — shared by the
// summed-area passes, the pipeline and the summed-area reference.
#pragma once

#include <summed_area.h>  // glsl/summed_area.h: PN_SUMMED_AREA_*, shared with the shader

namespace pn {

inline constexpr int kSummedAreaFractionBits = PN_SUMMED_AREA_FRACTION_BITS;
inline constexpr int kSummedAreaMagnitudeBits = PN_SUMMED_AREA_MAGNITUDE_BITS;
inline constexpr int kSummedAreaMaxSide = PN_SUMMED_AREA_MAX_SIDE;
inline constexpr int kSummedAreaMomentBits = PN_SUMMED_AREA_MOMENT_BITS;
inline constexpr int kSummedAreaMaxMomentBits = PN_SUMMED_AREA_MAX_MOMENT_BITS;

}  // namespace pn
