// C++ face of glsl/pcss_regions.glsl: which texels stand for a region, the
// refinement's bound and the lit marker — shared by the regions pass, the
// pipeline's settings and the regions' reference.
#pragma once

#include <cmath>
#include <string>

#include "core/format.h"

#include <pcss_regions.h>  // glsl/pcss_regions.h: PN_REGION_*, PN_REFINE_MAX_ITERATIONS, shared with the shaders

namespace pn {

// Which texels stand for a region of centre (x, y) and side s (pcss_regions.glsl).
enum class RegionMode {
  window = PN_REGION_WINDOW,    // the paper's power-of-two window, Steps 1-7 literally (region.glsl)
  exact = PN_REGION_EXACT,      // the n×n texels nearest the centre, n = round(s) (no approximation)
  centred = PN_REGION_CENTRED,  // the window's side, centred on (x, y) (pnRegionApproximateCentred)
};

// The largest filter scale c (filter side = c · penumbra) a technique takes: PCSS uses 1; past a
// few penumbrae the filter only blurs, and its cost grows as c² (exact PCSS, the scans).
inline constexpr float kMaxFilterScale = 64.0f;

// Whether `c` is a filter scale a technique takes (finite, 0..kMaxFilterScale), and what the
// error for one that is not expects.
inline bool valid_filter_scale(float c) { return std::isfinite(c) && c >= 0.0f && c <= kMaxFilterScale; }
inline std::string expected_filter_scale() { return "0.." + format_number("%g", kMaxFilterScale) + " (the filter side in penumbrae)"; }

// The module's loop bound (pcss_regions.h): more iterations than this refine no further.
inline constexpr int kRefineMaxIterations = PN_REFINE_MAX_ITERATIONS;

// The side of an entry known to be lit.
inline constexpr double kRegionLit = PN_REGION_LIT;

}  // namespace pn
