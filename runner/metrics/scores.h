// How close a visibility image is to a reference, on the pixels a viewer sees
// (SPEC §4.9): SSIM and mean absolute error over the whole soft-shadow map,
// over the pixels whose surface faces the light (N·L > 0: surfaces facing
// away are dark from shading, and acne there is no shadow technique's error —
// the headline), and over the lit image (its luma, metrics/lit_image.h).
#pragma once

#include "core/image.h"

namespace pn {

struct ImageScore {
  double ssim = 0.0;
  double mae = 0.0;
};

// A depth bias's two errors, on light-facing pixels (issue 25): acne — the mean darkening,
// max(reference − observed, 0), where the reference is fully lit (>= kFullyLit: the receiver
// shadows itself); leak — the mean brightening, max(observed − reference, 0), where the reference
// is fully shadowed (<= 1 − kFullyLit: the light under a blocker's contact, peter-panning). 0 where
// no pixel counts.
struct BiasErrors {
  double acne = 0.0, leak = 0.0;
};
inline constexpr double kFullyLit = 0.99;

struct Scores {
  ImageScore whole, light_facing, lit;
  BiasErrors bias;  // on the light-facing pixels
};

// Mean |a − b| over the texels where `mask` (same size, one channel) is non-zero, or over all
// texels when mask is null; 0 when none count. Throws Error for images of different sizes.
double mean_absolute_error(const Image& a, const Image& b, const Image* mask = nullptr);

// 1 where the surface faces the light: `surface` is SurfaceRenderer's image (channel 3: max(N·L, 0)).
Image light_facing_mask(const Image& surface);

// The two over the texels where `mask` is non-zero (all without one); single-channel images of one size.
BiasErrors bias_errors(const Image& reference, const Image& observed, const Image* mask = nullptr);

// Scores against one reference on one surface: the light-facing mask and the
// reference's lit luma are made once, for every image scored against it.
class VisibilityScorer {
 public:
  // `reference`: single-channel visibility, the size of `surface`.
  VisibilityScorer(Image reference, Image surface);
  Scores score(const Image& observed) const;

 private:
  Image reference_, surface_, facing_, lit_reference_;
};

// `reference` and `observed`: single-channel visibility, same size as `surface`.
Scores score_visibility(const Image& reference, const Image& observed, const Image& surface);

}  // namespace pn
