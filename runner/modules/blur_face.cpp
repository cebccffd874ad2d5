#include "modules/blur_face.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/format.h"

namespace pn {

void BlurParams::validate() const {
  if (radius < 0 || radius > kBlurMaxRadius)
    throw Error("blur radius " + std::to_string(radius) + ": expected an integer from 0 to " +
                std::to_string(kBlurMaxRadius));
  if (!std::isfinite(sigma) || sigma <= 0.0)
    throw Error("blur sigma " + format_number("%g", sigma) + ": expected a finite number > 0 (texels)");
  if (!std::isfinite(depth_tolerance) || depth_tolerance < 0.0)
    throw Error("blur depth tolerance " + format_number("%g", depth_tolerance) + ": expected a finite number >= 0");
  if (!std::isfinite(pixels_per_texel) || pixels_per_texel <= 0.0f)
    throw Error("blur pixels per texel " + format_number("%g", pixels_per_texel) +
                ": expected a finite number > 0 (screen pixels per shadow-map texel)");
}

double gaussian_weight(int offset, double sigma) {
  const double t = offset / sigma;
  return std::exp(-0.5 * t * t);
}

std::vector<double> normalised_gaussian(int radius, double sigma) {
  std::vector<double> w(static_cast<size_t>(2 * radius + 1));
  double sum = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    w[static_cast<size_t>(i + radius)] = gaussian_weight(i, sigma);
    sum += w[static_cast<size_t>(i + radius)];
  }
  for (double& v : w) v /= sum;
  return w;
}

}  // namespace pn
