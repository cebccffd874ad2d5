// PCSS against its brute force on the CPU (reference/pcss_reference.h): how the pipeline,
// fast_pcss and exports checks compare a GPU visibility with exact_pcss_reference or
// pcf_plane_reference.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/image.h"
#include "reference/pcss_reference.h"

namespace pn {

// The decision margin (texels for the squares' roundings, relative depth near dP - bias) within
// which float and double may round apart, and an occluded fraction's rounding (count / texels).
inline constexpr double kPcssDecisionMargin = 1e-4;
inline constexpr double kFractionRounding = 1e-6;

// Exact PCSS with area-weighted edges (exact_pcss_area_reference, issue 51) on an n² map: within
// kAreaEdgeMargin texels of a square's edge the blocker decision may round apart; what rounds in
// the visibility is each square's edges, formed in float from a centre within 5n and a side within
// 4n (4u · 9n a texel, 16u more of the side through the blocker mean and the light model), which
// moves an area fraction by at most 4 edge / side (side >= 1), and the float sums ((k + 2) u, k <= n²).
inline constexpr double kAreaEdgeMargin = 1e-3;
inline double area_edges_rounding(int n) {
  const double u = 0x1p-24, edge = 4.0 * u * 9.0 * n + 16.0 * u * 4.0 * n;
  return 4.0 * edge + (static_cast<double>(n) * n + 2.0) * u;
}

// What a square with area-weighted edges (pnRegionArea) of side `side` centred on (x, y) on an n²
// map can move its sums by through its corners' rounding: each corner formed in float from a centre
// within 5n and a side clamped to [1, 4n] (a non-finite side as 4n), 4 ulps of their magnitude, on
// each of the up to 4 (side + 2) edge texels (the side clipped to the map). In texels of weight.
inline double area_corner_error(double x, double y, double side, int n) {
  const double u = 0x1p-24;
  const double c = std::max(std::isfinite(x) ? std::fabs(x) : 0.0, std::isfinite(y) ? std::fabs(y) : 0.0);
  const double s = std::isfinite(side) ? std::clamp(side, 1.0, 4.0 * n) : 4.0 * n;
  return 4.0 * u * (std::min(c, 5.0 * n) + s) * 4.0 * (std::min(s, n + 0.0) + 2.0);
}

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
