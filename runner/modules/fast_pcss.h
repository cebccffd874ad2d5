// C++ face of glsl/fast_pcss.glsl: Fast PCSS's shipped defaults (the `fast`
// technique's settings, pipeline/pcss_settings.cpp) and the blocker-leaf
// sentinel its settings block carries.
#pragma once

#include <fast_pcss.h>  // glsl/fast_pcss.h: PN_FAST_PCSS_*, shared with the shaders

namespace pn {

inline constexpr int kFastPcssRefineIterations = PN_FAST_PCSS_REFINE_ITERATIONS;
inline constexpr int kFastPcssLeafSide = PN_FAST_PCSS_LEAF_SIDE;
inline constexpr int kFastPcssNodeBudget = PN_FAST_PCSS_NODE_BUDGET;
inline constexpr int kFastPcssSameLeafMode = PN_FAST_PCSS_SAME_LEAF_MODE;  // blockerLeafMode: "as leafMode"

}  // namespace pn
