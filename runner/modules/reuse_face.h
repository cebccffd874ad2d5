// C++ face of glsl/reuse.glsl: Eq. 7's thresholds and the tile of the
// representative scheme, shared by the reuse pass, the pipeline and the
// reuse's reference.
#pragma once

#include <reuse.h>  // glsl/reuse.h: PN_REUSE_MAX_TILE and the parent codes, shared with the shaders

namespace pn {

inline constexpr int kReuseMaxTile = PN_REUSE_MAX_TILE;

struct ReuseParams {
  float sigma1 = 0.0f;  // region side
  float sigma2 = 0.1f;  // region centre x, y
  float sigma3 = 0.1f;  // depth
  int tile = 4;         // k: 4 for Step 4, 2 for Step 5

  // Throws Error for negative or NaN sigmas and tiles outside 1…kReuseMaxTile.
  void validate() const;
};

}  // namespace pn
