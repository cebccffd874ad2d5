#include "metrics/ssim.h"

#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"
#include "modules/blur_face.h"

namespace pn {
namespace {

// Separable Gaussian-weighted sum over the window of every pixel whose window
// fits: a (w − 2r)×(h − 2r) result, in double.
std::vector<double> window_mean(const std::vector<double>& v, int w, int h, const std::vector<double>& g, int r) {
  const int ow = w - 2 * r, oh = h - 2 * r;
  std::vector<double> rows(static_cast<size_t>(ow) * h), out(static_cast<size_t>(ow) * oh);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < ow; ++x) {
      double s = 0.0;
      for (int i = 0; i <= 2 * r; ++i) s += g[static_cast<size_t>(i)] * v[static_cast<size_t>(y) * w + x + i];
      rows[static_cast<size_t>(y) * ow + x] = s;
    }
  for (int y = 0; y < oh; ++y)
    for (int x = 0; x < ow; ++x) {
      double s = 0.0;
      for (int i = 0; i <= 2 * r; ++i) s += g[static_cast<size_t>(i)] * rows[static_cast<size_t>(y + i) * ow + x];
      out[static_cast<size_t>(y) * ow + x] = s;
    }
  return out;
}

}  // namespace

namespace {

// The SSIM of every pixel whose window fits, row-major over (w − 2r)×(h − 2r), the window's centre at (x + r, y + r).
std::vector<double> ssim_map(const Image& a, const Image& b, const SsimParams& p) {
  if (a.width != b.width || a.height != b.height || a.channels != 1 || b.channels != 1)
    throw Error("SSIM of a " + std::to_string(a.width) + "x" + std::to_string(a.height) + " and a " +
                std::to_string(b.width) + "x" + std::to_string(b.height) +
                " image: expected two single-channel images of the same size");
  const int r = p.radius, w = a.width, h = a.height;
  if (w < 2 * r + 1 || h < 2 * r + 1)
    throw Error("SSIM of a " + std::to_string(w) + "x" + std::to_string(h) + " image: expected at least " +
                std::to_string(2 * r + 1) + "x" + std::to_string(2 * r + 1) + " (the window)");
  const size_t n = a.texels.size();
  std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(a.texels[i]) || !std::isfinite(b.texels[i]))
      throw Error("SSIM input has a non-finite value at texel " + std::to_string(i) + ": expected finite images");
    x[i] = a.texels[i], y[i] = b.texels[i];
    xx[i] = x[i] * x[i], yy[i] = y[i] * y[i], xy[i] = x[i] * y[i];
  }
  const std::vector<double> g = normalised_gaussian(r, p.sigma);
  const auto mx = window_mean(x, w, h, g, r), my = window_mean(y, w, h, g, r);
  const auto mxx = window_mean(xx, w, h, g, r), myy = window_mean(yy, w, h, g, r), mxy = window_mean(xy, w, h, g, r);
  const double c1 = (p.k1 * p.data_range) * (p.k1 * p.data_range), c2 = (p.k2 * p.data_range) * (p.k2 * p.data_range);
  std::vector<double> out(mx.size());
  for (size_t i = 0; i < mx.size(); ++i) {
    const double vx = mxx[i] - mx[i] * mx[i], vy = myy[i] - my[i] * my[i], cxy = mxy[i] - mx[i] * my[i];
    out[i] = ((2 * mx[i] * my[i] + c1) * (2 * cxy + c2)) / ((mx[i] * mx[i] + my[i] * my[i] + c1) * (vx + vy + c2));
  }
  return out;
}

}  // namespace

double ssim(const Image& a, const Image& b, const SsimParams& p) {
  const std::vector<double> map = ssim_map(a, b, p);
  double sum = 0.0;
  for (double v : map) sum += v;
  return sum / static_cast<double>(map.size());
}

double ssim(const Image& a, const Image& b, const Image& mask, const SsimParams& p) {
  if (mask.width != a.width || mask.height != a.height || mask.channels != 1)
    throw Error("SSIM mask " + std::to_string(mask.width) + "x" + std::to_string(mask.height) +
                ": expected a single-channel image the size of the compared ones");
  const std::vector<double> map = ssim_map(a, b, p);
  const int r = p.radius, ow = a.width - 2 * r;
  double sum = 0.0;
  long count = 0;
  for (size_t i = 0; i < map.size(); ++i) {
    const int x = static_cast<int>(i % static_cast<size_t>(ow)) + r, y = static_cast<int>(i / static_cast<size_t>(ow)) + r;
    if (mask.at(x, y) != 0.0f) sum += map[i], ++count;
  }
  return count > 0 ? sum / static_cast<double>(count) : 1.0;
}

}  // namespace pn
