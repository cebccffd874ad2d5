// C++ face of glsl/fast_pcss.glsl and glsl/hqepcss.glsl: Fast PCSS's shipped
// defaults and HQEPCSS's (the `fast` and `hqepcss` techniques' settings,
// pipeline/pcss_settings.cpp), and the blocker-leaf sentinel pnFastPcss's
// settings carry.
#pragma once

#include <fast_pcss.h>  // glsl/fast_pcss.h: PN_FAST_PCSS_*, shared with the shaders
#include <hqepcss.h>    // glsl/hqepcss.h: PN_HQEPCSS_*

#include "modules/traversal_face.h"  // LeafMode

namespace pn {

inline constexpr int kFastPcssRefineIterations = PN_FAST_PCSS_REFINE_ITERATIONS;
inline constexpr int kFastPcssLeafSide = PN_FAST_PCSS_LEAF_SIDE;
inline constexpr int kFastPcssLeafDivisor = PN_FAST_PCSS_LEAF_DIVISOR;  // the work budget (issue 52)
inline constexpr LeafMode kFastPcssLeafMode = static_cast<LeafMode>(PN_FAST_PCSS_LEAF_MODE);
inline constexpr int kFastPcssNodeBudget = PN_FAST_PCSS_NODE_BUDGET;
inline constexpr int kFastPcssSameLeafMode = PN_FAST_PCSS_SAME_LEAF_MODE;  // blockerLeafMode: "as leafMode"
inline constexpr int kHqepcssRefineIterations = PN_HQEPCSS_REFINE_ITERATIONS;  // hqepcss.glsl's defaults
inline constexpr int kHqepcssLeafSide = PN_HQEPCSS_LEAF_SIDE;

}  // namespace pn
