// CPU reference for exact PCSS (SPEC §4.8), from the definition: for each
// screen pixel of a G-buffer (u, v, light depth, valid), scan every texel of
// the search square (PCSS's width for blockers at the near plane), average
// the depths below dP - bias, penumbra by Eq. (1), and count the occluding
// texels of the filter square — in double precision, from LightModel.
// A square of side s around (x, y) is the n×n texels, n = max(1, round(s)),
// whose centres are nearest (x, y), clipped to the map: pcss_square, defined
// with the other regions of PCSS in pcss_regions_reference.h.
#pragma once

#include "core/image.h"
#include "reference/pcss_regions_reference.h"
#include "reference/traversal_reference.h"
#include "scene/light_model.h"

namespace pn {

struct PcssReference {
  Image visibility;  // 1 - occluded fraction; 1 where lit or no surface
  Image ambiguous;   // 1 where a rounding decision lay within `margin` of flipping (float may differ)
};

// `margin`: texels for the roundings of squares, relative to dP for depths near dP - bias.
// `receiver_plane_tan` > 0: with the receiver-plane depth bias (glsl/receiver_plane.glsl) — each
// pixel's plane from its G-buffer neighbours (receiver_plane_reference.h, slope clamped to this
// tangent times a texel's world width at dP), texel q occluding when d(q) < dP - bias + g · (q + ½ −
// (u, v)); a pixel whose plane float arithmetic could decide otherwise (a step choice near a tie,
// the steps near the parallel bound, the slope near its clamp) is ambiguous.
PcssReference exact_pcss_reference(const Image& shadow_map, const Image& gbuffer, const LightModel& light, double bias,
                                   double filter_scale, double margin, double receiver_plane_tan = 0.0);

// Exact PCSS with area-weighted edges (issue 51, PN_AREA_EDGES): both squares continuous and
// every texel weighed by its overlap (pcf_area_reference), blocker mean and occluded fraction as
// areas, the threshold the float dP - bias. Ambiguous where blockers lie within `margin` texels of
// the search square's edges and its occluded area is within their weight of none (an edge texel's
// weight, rounded, may be 0 or not: the blocker decision).
PcssReference exact_pcss_area_reference(const Image& shadow_map, const Image& gbuffer, const LightModel& light,
                                        float bias, double filter_scale, double margin);

// The hard shadow (2×2 bilinear PCF, pcf_reference.h) of each screen pixel with its G-buffer
// plane as exact_pcss_reference takes it (`receiver_plane_tan` > 0; 0: no plane): ambiguous where
// the plane is, or where a texel lies within `margin` (relative to the magnitudes) of its threshold.
PcssReference pcf_plane_reference(const Image& shadow_map, const Image& gbuffer, const LightModel& light, double bias,
                                  double margin, double receiver_plane_tan);

}  // namespace pn
