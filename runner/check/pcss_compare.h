// PCSS against its brute force on the CPU (reference/pcss_reference.h): how the pipeline,
// fast_pcss and exports checks compare a GPU visibility with exact_pcss_reference or
// pcf_plane_reference.
#pragma once

#include "core/image.h"
#include "reference/pcss_reference.h"

namespace pn {

// The decision margin (texels for the squares' roundings, relative depth near dP - bias) within
// which float and double may round apart, and an occluded fraction's rounding (count / texels).
inline constexpr double kPcssDecisionMargin = 1e-4;
inline constexpr double kFractionRounding = 1e-6;

// Sets `observed` to the reference where a decision lay within rounding of flipping (the
// reference's ambiguous pixels), so those are left out of the comparison; returns how many.
inline int leave_out_ambiguous(const PcssReference& reference, Image& observed) {
  int count = 0;
  for (int y = 0; y < observed.height; ++y)
    for (int x = 0; x < observed.width; ++x)
      if (reference.ambiguous.at(x, y) != 0.0f) observed.at(x, y) = reference.visibility.at(x, y), ++count;
  return count;
}

}  // namespace pn
