#include "metrics/lit_image.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "metrics/ssim.h"

namespace pn {
namespace {

std::string describe(const Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height) + "x" + std::to_string(image.channels);
}

// NaN becomes 0 (std::clamp would pass it through).
float unit(float v) { return v > 0.0f ? std::min(v, 1.0f) : 0.0f; }

}  // namespace

Image compose_lit_image(const Image& surface, const Image& visibility) {
  if (surface.channels != 4 || visibility.channels != 1 || surface.width != visibility.width ||
      surface.height != visibility.height)
    throw Error("lit image from surface " + describe(surface) + " and visibility " + describe(visibility) +
                ": expected W x H x 4 and W x H x 1");
  Image out(surface.width, surface.height, 3);
  for (int y = 0; y < surface.height; ++y)
    for (int x = 0; x < surface.width; ++x) {
      const bool sky = surface.at(x, y, 0) == 0 && surface.at(x, y, 1) == 0 && surface.at(x, y, 2) == 0 &&
                       surface.at(x, y, 3) == 0;
      const float light = kLitAmbient + (1 - kLitAmbient) * unit(surface.at(x, y, 3)) * unit(visibility.at(x, y));
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = sky ? kSkyColour[c] : unit(unit(surface.at(x, y, c)) * light);
    }
  return out;
}

Image luma(const Image& rgb) {
  if (rgb.channels != 3) throw Error("luma of a " + describe(rgb) + " image: expected 3 channels");
  Image out(rgb.width, rgb.height, 1);
  for (int y = 0; y < rgb.height; ++y)
    for (int x = 0; x < rgb.width; ++x)
      out.at(x, y) = 0.2126f * rgb.at(x, y, 0) + 0.7152f * rgb.at(x, y, 1) + 0.0722f * rgb.at(x, y, 2);
  return out;
}

double lit_ssim(const Image& surface, const Image& visibility_a, const Image& visibility_b) {
  return ssim(luma(compose_lit_image(surface, visibility_a)), luma(compose_lit_image(surface, visibility_b)));
}

}  // namespace pn
