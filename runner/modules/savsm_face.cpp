#include "modules/savsm_face.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/format.h"
#include "modules/pcss_regions_face.h"

namespace pn {

const char* savsm_blocker_name(SavsmBlocker blocker) {
  return blocker == SavsmBlocker::table ? "table" : "min";
}

void SavsmSettings::validate() const {
  const auto bad = [](const char* what, float v, const char* expected) {
    return Error(std::string("savsm ") + what + " " + format_number("%g", v) + ": expected " + expected);
  };
  if (!std::isfinite(bias) || bias < 0.0f) throw bad("bias", bias, "a finite number >= 0");
  if (!valid_filter_scale(filter_scale)) throw bad("filter scale", filter_scale, expected_filter_scale().c_str());
  if (!std::isfinite(min_variance) || min_variance < 0.0f) throw bad("min variance", min_variance, "a finite number >= 0");
  if (!(bleeding_reduction >= 0.0f && bleeding_reduction <= static_cast<float>(kVsmMaxBleedingReduction)))
    throw bad("bleeding reduction", bleeding_reduction, "a number from 0 to 0.99 (PN_VSM_MAX_BLEEDING_REDUCTION)");
}

}  // namespace pn
