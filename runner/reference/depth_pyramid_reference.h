// CPU references for glsl/depth_pyramid.glsl, from the definition: each
// level-i texel is the min / max / mean over the texels of its 2^i×2^i
// window, found by scanning them — never by combining smaller windows.
#pragma once

#include <utility>

#include "core/image.h"
#include "modules/depth_pyramid_face.h"

namespace pn {

// SPEC §3: a NaN or ±Inf depth is "no occluder", i.e. +Inf (far).
float sanitize_depth(float depth);

// min, max and mean (double) of the side×side window at (u, v), by scanning every texel.
struct WindowStats {
  float min;
  float max;
  double mean;
};
WindowStats window_stats(const Image& map, int u, int v, int side);

// Level `level` of an N×N map: an (N − 2^level + 1)² image of (min, max, mean).
// Each window is still a scan of its own texels, done row segment by row
// segment (the min over a window is the min over its rows of the min over
// each row's segment), which keeps large maps affordable.
Image pyramid_level_reference(const Image& map, int level);

// The map with every depth passed through sanitize_depth.
Image sanitized_depths(const Image& map);

// (min, max) of any side×side square at (u, v) of an already sanitized map, by scanning it.
std::pair<float, float> square_min_max(const Image& depth, int u, int v, int side);

}  // namespace pn
