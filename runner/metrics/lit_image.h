// A lit picture from the surface pass and a visibility image (a soft-shadow
// result or the physical reference): albedo x (ambient + (1 - ambient) x
// cos x visibility), sky where no surface is seen. CPU only, so every
// technique's visibility is lit by the same formula.
#pragma once

#include <array>

#include "core/image.h"

namespace pn {

inline constexpr float kLitAmbient = 0.25f;
inline constexpr std::array<float, 3> kSkyColour{0.62f, 0.75f, 0.90f};

// `surface`: 4 channels (SurfaceRenderer: albedo rgb, max(dot(N, L), 0)); `visibility`: 1 channel in
// [0, 1], same size. Returns 3 channels in [0, 1], same rows. A pixel whose four surface channels are
// all 0 is sky. Throws Error when the sizes or channel counts differ from that.
Image compose_lit_image(const Image& surface, const Image& visibility);

// Rec. 709 luma of a 3-channel image: the single channel SSIM compares for lit pictures.
Image luma(const Image& rgb);

// SSIM of the lit pictures (their luma) that two visibility images give on the same surface.
double lit_ssim(const Image& surface, const Image& visibility_a, const Image& visibility_b);

}  // namespace pn
