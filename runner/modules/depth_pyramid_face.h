// C++ face of glsl/depth_pyramid.glsl: how many levels a map's pyramid has,
// shared by the pyramid and mip-chain passes, the pipeline, the caches and the
// pyramid's reference.
#pragma once

namespace pn {

// floor(log2 n) for n >= 1.
int floor_log2(int n);

// Number of pyramid levels for an N×N map and a maximum level: min(floor(log2 N), max_level) + 1.
// Throws Error for N < 2 or max_level < 0.
int pyramid_level_count(int n, int max_level);

}  // namespace pn
