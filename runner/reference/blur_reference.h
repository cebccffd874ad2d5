// CPU references for glsl/blur.glsl, written from the definition, not from
// the shader: the plain blur is the direct 2-D convolution with the product
// kernel w_i w_j (never separated); the depth-aware blur is defined as two 1-D
// passes and is computed that way, each tap by its own rule; so is the
// adaptive blur (each output pixel its own radius, from its filter side).
// Every channel of the source is blurred alike, each on its own (moments:
// glsl/vsm.glsl); depth and filter maps are read as one image for all.
#pragma once

#include <vector>

#include "core/image.h"
#include "modules/blur_face.h"

namespace pn {

Image blur_reference(const Image& source, const BlurParams& params);
Image blur_depth_aware_reference(const Image& source, const Image& depth, const BlurParams& params);

// The adaptive radius of a pixel whose filter region has side `filter_side`
// texels (< 0 or NaN: lit): floor(s k / 2) in float arithmetic, as the module
// computes it, clamped to [0, radius]; 0 when k is not > 0.
int blur_adaptive_radius(float filter_side, float pixels_per_texel, int radius);

// params.adaptive's blur: two 1-D passes (x, then y), each output pixel p
// summing the taps within its own radius r(p) (blur_adaptive_radius of the
// side in channel 3 of `filter_map`, an RGBA (d, x, y, s) map of the source's
// size), weights gaussian_weight(i) renormalised over the taps kept; with
// params.depth_aware, taps off p's surface in `depth` are dropped as in
// blur_depth_aware_reference. `depth` is read only when params.depth_aware.
Image blur_adaptive_reference(const Image& source, const Image& filter_map, const Image* depth,
                              const BlurParams& params);

}  // namespace pn
