#include "figures/lit_image.h"

#include <algorithm>
#include <string>

#include "core/error.h"

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

}  // namespace pn
