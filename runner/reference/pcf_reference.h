// CPU reference for glsl/pcf.glsl, written from its definition: clip the
// window to the map, keep at most `max_side` columns and rows of what is left
// (from its top-left texel), and scan every texel in double — a texel of
// depth d occludes receiver depth dP when d is finite and d < dP - bias
// (SPEC §3). Nothing is sanitised beforehand: the map is the raw input.
#pragma once

#include <functional>

#include "core/image.h"
#include "core/texel_rect.h"
#include "modules/pcf_face.h"

namespace pn {

struct PcfSums {
  long occluders = 0;
  double depth_sum = 0.0;
  long texels = 0;  // covered: inside the map and within the bound

  double blocker_mean() const { return occluders > 0 ? depth_sum / static_cast<double>(occluders) : 0.0; }
  double occluded_fraction() const {
    return texels > 0 ? static_cast<double>(occluders) / static_cast<double>(texels) : 0.0;
  }
};

// The covered part of `window` on a width × height map: [x0, x1) × [y0, y1).
struct PcfCover {
  long x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
PcfCover pcf_cover(const Rect& window, int map_width, int map_height, int max_side = kPcfMaxSide);

// `depth` is the raw single-channel map (NaN and ±Inf allowed).
PcfSums pcf_reference(const Image& depth, const Rect& window, double receiver_depth, double bias,
                      int max_side = kPcfMaxSide);

// The area-weighted window (issue 51: pnRegionArea + pnPcfAreaPlane), from its definition: the
// continuous square of side clamp(side, 1, 4N) centred on (x, y) — a NaN coordinate read as 0, the
// centre clamped to [-4N, 5N], a NaN or negative side as 0, as the module reads its inputs — and
// every texel [i, i+1) × [j, j+1) of the map weighed by the area of its overlap with it, in
// double: occluders = that area over the texels of finite depth < threshold, depth_sum = the
// area-weighted depths of those, area = the overlap of the square with the map. `threshold` is the
// float dP - bias the module forms (the caller computes it in float).
// The texels of that square on a width × height map, each with its overlap weight w > 0 (the
// geometry pcf_area_reference and the traversal's area reference share).
void for_each_area_texel(int width, int height, double x, double y, double side,
                         const std::function<void(int, int, double)>& visit);

struct PcfAreaSums {
  double occluders = 0.0, depth_sum = 0.0, area = 0.0;
  int touched = 0;  // texels of non-zero weight
};
PcfAreaSums pcf_area_reference(const Image& depth, double x, double y, double side, float threshold);

// Both with a receiver plane (pnPcfWindowPlane, pnPcfAreaPlane and their bands): texel q against its
// own threshold receiver_plane_threshold(t, g · (q + ½ − c)) — the plane through the receiver at c,
// never above t (the float dP − bias the caller formed) — in double. `open` is set where a finite
// texel's depth lies within `band` (relative to the magnitudes) of its threshold: float may decide
// it either way.
struct PlanePcf {
  double gradient_u = 0.0, gradient_v = 0.0, centre_u = 0.0, centre_v = 0.0, band = 0.0;
};
PcfSums pcf_reference_plane(const Image& depth, const Rect& window, float threshold, const PlanePcf& plane, bool& open,
                            int max_side = kPcfMaxSide);
PcfAreaSums pcf_area_reference_plane(const Image& depth, double x, double y, double side, float threshold,
                                     const PlanePcf& plane, bool& open);

}  // namespace pn

namespace pn {

// 2×2 bilinear PCF (pnPcfBilinearVisibility) from its definition: the four texels whose
// centres (i + 0.5) surround (x, y), clamped to the map, each lit unless its depth d is
// finite and d < threshold (the float dP − bias the caller computed), weighted by the
// bilinear weights of (x − 0.5, y − 0.5)'s fractional part, in double. A NaN or infinite
// position is lit.
double pcf_bilinear_reference(const Image& depth, double x, double y, float threshold);

// The same with a receiver plane (pnPcfBilinearVisibilityPlane): each texel q read (after the
// clamp) against its own threshold d − bias + g · (q + ½ − (x, y)), in double. `open`: a texel
// within `band` (relative to the magnitudes involved) of its threshold, which float rounding
// may decide either way.
struct BilinearPlane {
  double visibility = 1.0;
  bool open = false;
};
BilinearPlane pcf_bilinear_reference_plane(const Image& depth, double x, double y, double receiver_depth,
                                           double gradient_u, double gradient_v, double bias, double band);

}  // namespace pn
