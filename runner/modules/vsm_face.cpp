#include "modules/vsm_face.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/format.h"

namespace pn {
namespace {

void require_finite(const char* what, double v, const char* expected) {
  if (!std::isfinite(v)) throw Error(std::string(what) + " " + format_number("%g", v) + ": expected " + expected);
}

}  // namespace

const char* vsm_kind_name(VsmKind kind) {
  switch (kind) {
    case VsmKind::vsm: return "vsm";
    case VsmKind::evsm2: return "evsm2";
    case VsmKind::evsm4: return "evsm4";
  }
  return "?";
}

int vsm_moment_channels(VsmKind kind) { return kind == VsmKind::evsm4 ? 4 : 2; }

void VsmParams::validate() const {
  blur.validate();
  require_finite("vsm min variance", min_variance, "a finite number >= 0 (relative to the squared mean)");
  if (min_variance < 0.0f)
    throw Error("vsm min variance " + format_number("%g", min_variance) + ": expected a finite number >= 0");
  if (!(bleeding_reduction >= 0.0f && bleeding_reduction <= kVsmMaxBleedingReduction))
    throw Error("vsm bleeding reduction " + format_number("%g", bleeding_reduction) + ": expected 0 to " +
                format_number("%g", kVsmMaxBleedingReduction));
  require_finite("vsm near depth", near_depth, "a finite depth");
  require_finite("vsm far depth", far_depth, "a finite depth");
  if (!(far_depth > near_depth))
    throw Error("vsm depth range " + format_number("%g", near_depth) + ".." + format_number("%g", far_depth) +
                ": expected near < far");
  for (float c : {positive_exponent, negative_exponent})
    if (!(c >= 0.0f && c <= kEvsmMaxExponent))
      throw Error("evsm exponent " + format_number("%g", c) + ": expected 0 to " +
                  format_number("%g", kEvsmMaxExponent) + " (fp32 overflow bound, glsl/vsm.h)");
}

}  // namespace pn
