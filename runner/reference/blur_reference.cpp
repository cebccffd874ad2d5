#include "reference/blur_reference.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "core/format.h"

namespace pn {
namespace {

float finite_or(float v, float fallback) { return std::isfinite(v) ? v : fallback; }

int clamp_index(int i, int size) { return std::clamp(i, 0, size - 1); }

}  // namespace

Image blur_reference(const Image& source, const BlurParams& params) {
  const int r = params.radius;
  const std::vector<double> w = normalised_gaussian(r, params.sigma);
  Image out(source.width, source.height, source.channels);
  for (int c = 0; c < source.channels; ++c) {
    for (int y = 0; y < source.height; ++y) {
      for (int x = 0; x < source.width; ++x) {
        double sum = 0.0;
        for (int j = -r; j <= r; ++j) {
          for (int i = -r; i <= r; ++i) {
            const float v = source.at(clamp_index(x + i, source.width), clamp_index(y + j, source.height), c);
            sum += w[static_cast<size_t>(i + r)] * w[static_cast<size_t>(j + r)] * finite_or(v, kBlurNonfiniteValue);
          }
        }
        out.at(x, y, c) = static_cast<float>(sum);
      }
    }
  }
  return out;
}

namespace {

// The depth-aware cut, in float arithmetic on float depths as the module
// defines it (deciding it in double would move the threshold by a rounding
// step): a tap lies on the centre's surface when both are finite and within
// tol relative, or both are not finite.
bool same_surface(float centre, float tap, float tol) {
  if (!std::isfinite(centre) || !std::isfinite(tap)) return std::isfinite(centre) == std::isfinite(tap);
  return std::fabs(tap - centre) <= tol * std::fabs(centre);
}

// Two 1-D passes (x, then y): each output pixel p is the normalised Gaussian
// sum over the taps within radius_at(p) that kept(p, tap) accepts (the centre
// always counts).
template <class Radius, class Kept>
Image two_pass_blur(const Image& source, double sigma, Radius radius_at, Kept kept) {
  auto pass = [&](const Image& in, int dx, int dy) {
    Image out(in.width, in.height, in.channels);
    for (int c = 0; c < in.channels; ++c) {
      for (int y = 0; y < in.height; ++y) {
        for (int x = 0; x < in.width; ++x) {
          const int r = radius_at(x, y);
          double sum = 0.0, weight_sum = 0.0;
          for (int i = -r; i <= r; ++i) {
            const int qx = clamp_index(x + i * dx, in.width), qy = clamp_index(y + i * dy, in.height);
            if (i != 0 && !kept(x, y, qx, qy)) continue;
            const double weight = gaussian_weight(i, sigma);
            sum += weight * finite_or(in.at(qx, qy, c), kBlurNonfiniteValue);
            weight_sum += weight;
          }
          out.at(x, y, c) = static_cast<float>(sum / weight_sum);
        }
      }
    }
    return out;
  };
  return pass(pass(source, 1, 0), 0, 1);
}

}  // namespace

Image blur_depth_aware_reference(const Image& source, const Image& depth, const BlurParams& params) {
  const float tol = static_cast<float>(params.depth_tolerance);
  return two_pass_blur(
      source, params.sigma, [&](int, int) { return params.radius; },
      [&](int x, int y, int qx, int qy) { return same_surface(depth.at(x, y), depth.at(qx, qy), tol); });
}

int blur_adaptive_radius(float filter_side, float pixels_per_texel, int radius) {
  if (!(pixels_per_texel > 0.0f)) return 0;
  const float half_width = 0.5f * filter_side * pixels_per_texel;  // float, as the module
  if (!(half_width >= 1.0f)) return 0;                               // lit, NaN, contact
  return half_width >= static_cast<float>(radius) ? radius : static_cast<int>(std::floor(half_width));
}

Image blur_adaptive_reference(const Image& source, const Image& filter_map, const Image* depth,
                              const BlurParams& params) {
  if (filter_map.width != source.width || filter_map.height != source.height || filter_map.channels != 4)
    throw Error("adaptive blur reference: expected a 4-channel filter map of the source's size");
  if (params.depth_aware && (depth == nullptr || depth->width != source.width || depth->height != source.height))
    throw Error("adaptive blur reference: the depth-aware variant expects a depth image of the source's size");
  const float tol = static_cast<float>(params.depth_tolerance);
  return two_pass_blur(
      source, params.sigma,
      [&](int x, int y) { return blur_adaptive_radius(filter_map.at(x, y, 3), params.pixels_per_texel, params.radius); },
      [&](int x, int y, int qx, int qy) {
        return !params.depth_aware || same_surface(depth->at(x, y), depth->at(qx, qy), tol);
      });
}

}  // namespace pn
