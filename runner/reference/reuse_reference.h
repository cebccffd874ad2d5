// CPU reference for glsl/reuse.glsl: Eq. 7 with the larger value as divisor,
// explicit parent pointers, and roots found by following them.
#pragma once

#include <vector>

#include "core/image.h"
#include "modules/reuse_face.h"

namespace pn {

// Eq. 7 on two entries (d, x, y, s).
bool reuse_similar(const float a[4], const float b[4], const ReuseParams& params);

// Parent of each pixel of an RGBA (d, x, y, s) image, as a linear index y·W + x, or −1.
std::vector<int> reuse_parents(const Image& entries, const ReuseParams& params);

// The representative (root) of each pixel, by following parent pointers.
std::vector<int> reuse_roots(const std::vector<int>& parents);

}  // namespace pn
