// C++ face of glsl/savsm.glsl (summed-area variance soft shadows): its
// settings, blocker estimates, fetch bounds and one receiver's query — shared
// by the savsm passes, the savsm techniques and the savsm reference.
#pragma once

#include <savsm.h>  // glsl/savsm.h: PN_SAVSM_*, shared with the shader

#include "modules/vsm_face.h"  // PN_VSM_* defaults and the bleeding bound

namespace pn {

inline constexpr double kSavsmMinOccluded = PN_SAVSM_MIN_OCCLUDED;
inline constexpr int kSavsmRectFetches = PN_SAVSM_RECT_FETCHES;
inline constexpr int kSavsmMaxSquareFetches = PN_SAVSM_MAX_SQUARE_FETCHES;
// A receiver's most texel fetches (savsm.glsl's cost): two table rectangles and two mip-chain squares.
inline constexpr int kSavsmMaxReceiverFetches = 2 * kSavsmRectFetches + 2 * kSavsmMaxSquareFetches;

enum class SavsmBlocker { table = PN_SAVSM_BLOCKER_TABLE, min = PN_SAVSM_BLOCKER_MIN };
const char* savsm_blocker_name(SavsmBlocker blocker);  // "table", "min"

struct SavsmSettings {
  float bias = 0.02f;                                                        // light-depth units
  float filter_scale = static_cast<float>(PN_SAVSM_FILTER_SCALE);             // c
  float min_variance = static_cast<float>(PN_VSM_MIN_VARIANCE);               // relative to mu^2
  float bleeding_reduction = static_cast<float>(PN_VSM_BLEEDING_REDUCTION);  // linstep's a
  SavsmBlocker blocker = static_cast<SavsmBlocker>(PN_SAVSM_DEFAULT_BLOCKER);  // the truth favours MIN (savsm.md)
  bool bound = PN_SAVSM_DEFAULT_BOUND != 0;  // the mip chain's lit test over the search square, depth-range bound over the filter

  // Whether the module reads the min/max mip chain: for the bound, or for the min blocker.
  bool reads_mip() const { return bound || blocker == SavsmBlocker::min; }

  // Throws Error naming the setting and its range: bias, scale finite >= 0, min variance finite
  // >= 0, bleeding in [0, PN_VSM_MAX_BLEEDING_REDUCTION].
  void validate() const;
};

struct SavsmReceiver {
  float u = 0.0f, v = 0.0f;  // shadow-map texels (texel i spans [i, i + 1))
  float depth = 0.0f;        // linear light depth
};

}  // namespace pn
