// CPU reference for glsl/reuse.glsl: Eq. 7 with the larger value as divisor,
// explicit parent pointers, and roots found by following them.
#pragma once

#include <vector>

#include "core/image.h"
#include "reuse.h"  // glsl/reuse.h: PN_REUSE_MAX_TILE and the parent codes, shared with the shaders

namespace pn {

struct ReuseParams {
  float sigma1 = 0.0f;  // region side
  float sigma2 = 0.1f;  // region centre x, y
  float sigma3 = 0.1f;  // depth
  int tile = 4;         // k: 4 for Step 4, 2 for Step 5

  // Throws Error for negative or NaN sigmas and tiles outside 1…kReuseMaxTile.
  void validate() const;
};

inline constexpr int kReuseMaxTile = PN_REUSE_MAX_TILE;

// Eq. 7 on two entries (d, x, y, s).
bool reuse_similar(const float a[4], const float b[4], const ReuseParams& params);

// Parent of each pixel of an RGBA (d, x, y, s) image, as a linear index y·W + x, or −1.
std::vector<int> reuse_parents(const Image& entries, const ReuseParams& params);

// The representative (root) of each pixel, by following parent pointers.
std::vector<int> reuse_roots(const std::vector<int>& parents);

}  // namespace pn
