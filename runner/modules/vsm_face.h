// C++ face of glsl/vsm.glsl: the kinds of moments (VSM, EVSM with two or four
// components), their limits and the parameters one shading takes — shared by
// the VSM passes, the vsm techniques and the VSM reference.
#pragma once

#include <vsm.h>  // glsl/vsm.h: PN_VSM_*, PN_EVSM_*, shared with the shader

#include "modules/blur_face.h"

namespace pn {

enum class VsmKind { vsm = PN_VSM_KIND_VSM, evsm2 = PN_VSM_KIND_EVSM2, evsm4 = PN_VSM_KIND_EVSM4 };

inline constexpr double kEvsmMaxExponent = PN_EVSM_MAX_EXPONENT;
inline constexpr double kVsmMaxBleedingReduction = PN_VSM_MAX_BLEEDING_REDUCTION;
inline constexpr float kVsmVarianceFloor = static_cast<float>(PN_VSM_VARIANCE_FLOOR);  // FLT_MIN
// A receiver's texel fetches (vsm.glsl's cost): its moments, and the pyramid's square for the bound.
inline constexpr int kVsmReceiverFetches = 1 + 4;

const char* vsm_kind_name(VsmKind kind);  // "vsm", "evsm2", "evsm4"
int vsm_moment_channels(VsmKind kind);    // 2, 2, 4

struct VsmParams {
  VsmKind kind = VsmKind::vsm;
  BlurParams blur;  // the moments' blur; its radius is also the depth-range bound's window (2r + 1)
  float min_variance = static_cast<float>(PN_VSM_MIN_VARIANCE);              // relative to mu^2
  float bleeding_reduction = static_cast<float>(PN_VSM_BLEEDING_REDUCTION);  // linstep's lower edge
  float near_depth = 0.0f, far_depth = 1.0f;  // EVSM's range; far is VSM's depth of non-finite texels
  float positive_exponent = static_cast<float>(PN_EVSM_POSITIVE_EXPONENT);
  float negative_exponent = static_cast<float>(PN_EVSM_NEGATIVE_EXPONENT);

  // Throws Error naming the parameter and the accepted range.
  void validate() const;
};

}  // namespace pn
