// Comparing a rasterised image with its ray-cast definition. Off silhouettes
// every channel agrees within `relative` · max(|expected|, 1). On a silhouette
// the rasteriser's fixed-point edge test and the exact ray may disagree about
// a pixel centre (almost) on an edge, and a face seen edge-on interpolates
// from vertices snapped to 1/256 pixel; such a pixel must satisfy `explained`.
// Two cases come back: the masked off-silhouette comparison (its name carries
// the silhouette count) and the silhouette property.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "check/module_check.h"

namespace pn {

using SilhouetteRule = std::function<bool(int x, int y)>;

std::vector<CaseResult> compare_raster(const std::string& name, const Image& expected, const Image& observed,
                                       double relative, const SilhouetteRule& explained, const std::string& rule);

// A silhouette rule: every channel of the observed pixel lies within the range
// its 3×3 neighbourhood's rays see, widened by `sliver` · max(|v|, 1).
SilhouetteRule within_neighbour_range(const Image& expected, const Image& observed, double sliver);

}  // namespace pn
