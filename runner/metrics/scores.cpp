#include "metrics/scores.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/error.h"
#include "metrics/lit_image.h"
#include "metrics/ssim.h"

namespace pn {

double mean_absolute_error(const Image& a, const Image& b, const Image* mask) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels ||
      (mask && (mask->width != a.width || mask->height != a.height || mask->channels != 1)))
    throw Error("mean absolute error of a " + std::to_string(a.width) + "x" + std::to_string(a.height) + " and a " +
                std::to_string(b.width) + "x" + std::to_string(b.height) + " image: expected the same sizes");
  double sum = 0.0;
  long count = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if (mask && mask->at(x, y) == 0.0f) continue;
      for (int c = 0; c < a.channels; ++c) sum += std::fabs(static_cast<double>(a.at(x, y, c)) - b.at(x, y, c));
      ++count;
    }
  return count > 0 ? sum / (static_cast<double>(count) * a.channels) : 0.0;
}

BiasErrors bias_errors(const Image& reference, const Image& observed, const Image* mask) {
  mean_absolute_error(reference, observed, mask);  // the same size checks
  double darker = 0.0, brighter = 0.0;
  long lit = 0, shadowed = 0;
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x) {
      if (mask && mask->at(x, y) == 0.0f) continue;
      const double r = reference.at(x, y), o = observed.at(x, y);
      if (r >= kFullyLit) darker += std::max(r - o, 0.0), ++lit;
      if (r <= 1.0 - kFullyLit) brighter += std::max(o - r, 0.0), ++shadowed;
    }
  return {lit > 0 ? darker / static_cast<double>(lit) : 0.0, shadowed > 0 ? brighter / static_cast<double>(shadowed) : 0.0};
}

Image light_facing_mask(const Image& surface) {
  Image mask(surface.width, surface.height);
  for (int y = 0; y < surface.height; ++y)
    for (int x = 0; x < surface.width; ++x) mask.at(x, y) = surface.at(x, y, 3) > 0.0f ? 1.0f : 0.0f;
  return mask;
}

VisibilityScorer::VisibilityScorer(Image reference, Image surface)
    : reference_(std::move(reference)),
      surface_(std::move(surface)),
      facing_(light_facing_mask(surface_)),
      lit_reference_(luma(compose_lit_image(surface_, reference_))) {}

Scores VisibilityScorer::score(const Image& observed) const {
  const Image lit_observed = luma(compose_lit_image(surface_, observed));
  Scores s;
  s.whole = {ssim(reference_, observed), mean_absolute_error(reference_, observed)};
  s.light_facing = {ssim(reference_, observed, facing_), mean_absolute_error(reference_, observed, &facing_)};
  s.lit = {ssim(lit_reference_, lit_observed), mean_absolute_error(lit_reference_, lit_observed)};
  s.bias = bias_errors(reference_, observed, &facing_);
  return s;
}

Scores score_visibility(const Image& reference, const Image& observed, const Image& surface) {
  return VisibilityScorer(reference, surface).score(observed);
}

}  // namespace pn
