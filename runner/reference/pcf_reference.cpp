#include "reference/pcf_reference.h"

#include <algorithm>
#include <functional>
#include <cmath>

#include "reference/receiver_plane_reference.h"

namespace pn {

PcfCover pcf_cover(const Rect& window, int map_width, int map_height, int max_side) {
  // In 64-bit: no overflow whatever the window.
  const auto axis = [max_side](long origin, long size, long extent, long& lo, long& hi) {
    lo = std::clamp(origin, 0L, extent);
    hi = std::clamp(origin + std::max(size, 0L), lo, extent);
    hi = std::min(hi, lo + static_cast<long>(max_side));
  };
  PcfCover c;
  axis(window.x, window.width, map_width, c.x0, c.x1);
  axis(window.y, window.height, map_height, c.y0, c.y1);
  return c;
}

PcfSums pcf_reference(const Image& depth, const Rect& window, double receiver_depth, double bias, int max_side) {
  const PcfCover c = pcf_cover(window, depth.width, depth.height, max_side);
  const double t = receiver_depth - bias;
  PcfSums s;
  for (long y = c.y0; y < c.y1; ++y)
    for (long x = c.x0; x < c.x1; ++x) {
      const double d = depth.at(static_cast<int>(x), static_cast<int>(y));
      ++s.texels;
      if (std::isfinite(d) && d < t) ++s.occluders, s.depth_sum += d;
    }
  return s;
}

void for_each_area_texel(int width, int height, double x, double y, double side,
                         const std::function<void(int, int, double)>& visit) {
  const double n = width;
  const auto centre = [&](double c) { return std::clamp(std::isnan(c) ? 0.0 : c, -4.0 * n, 5.0 * n); };
  const double s = std::clamp(std::isnan(side) ? 0.0 : std::max(side, 0.0), 1.0, 4.0 * n);
  const double x0 = centre(x) - 0.5 * s, x1 = centre(x) + 0.5 * s;
  const double y0 = centre(y) - 0.5 * s, y1 = centre(y) + 0.5 * s;
  const auto overlap = [](double a0, double a1, double b0, double b1) {
    return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
  };
  // Texels outside [floor(x0), ceil(x1)) overlap nothing: the loops skip them (a bound, not a clip:
  // every texel in it is weighed by the overlap above, zero or not).
  const auto first = [](double lo) { return static_cast<int>(std::max(0.0, std::floor(lo))); };
  const auto end = [](double hi, int n) { return static_cast<int>(std::min<double>(n, std::ceil(hi))); };
  for (int j = first(y0); j < end(y1, height); ++j) {
    const double wy = overlap(j, j + 1.0, y0, y1);
    if (wy == 0.0) continue;
    for (int i = first(x0); i < end(x1, width); ++i) {
      const double w = overlap(i, i + 1.0, x0, x1) * wy;
      if (w != 0.0) visit(i, j, w);
    }
  }
}

namespace {

// Whether texel (i, j) of depth d occludes under the plane; `open` where rounding may flip it.
bool plane_occludes(double d, int i, int j, float threshold, const PlanePcf& p, bool& open) {
  const double qx = i + 0.5 - p.centre_u, qy = j + 0.5 - p.centre_v;
  const double along = p.gradient_u * qx + p.gradient_v * qy;
  if (!std::isfinite(d)) return false;
  const double magnitude = std::fabs(threshold) + std::fabs(p.gradient_u) * (std::fabs(i) + std::fabs(p.centre_u) + 1.0) +
                           std::fabs(p.gradient_v) * (std::fabs(j) + std::fabs(p.centre_v) + 1.0);
  const double slack = p.band * magnitude;
  // Up the plane the threshold is the caller's float itself (the cap), exactly; down it (or within
  // rounding of the cap) the plane's value, rounded.
  if (along >= slack) return d < threshold;
  if (std::fabs(d - (threshold + along)) <= slack || (along > -slack && std::fabs(d - threshold) <= slack)) open = true;
  return d < receiver_plane_threshold(threshold, along);
}

}  // namespace

PcfSums pcf_reference_plane(const Image& depth, const Rect& window, float threshold, const PlanePcf& plane, bool& open,
                            int max_side) {
  const PcfCover c = pcf_cover(window, depth.width, depth.height, max_side);
  PcfSums s;
  for (long y = c.y0; y < c.y1; ++y)
    for (long x = c.x0; x < c.x1; ++x) {
      const double d = depth.at(static_cast<int>(x), static_cast<int>(y));
      ++s.texels;
      if (plane_occludes(d, static_cast<int>(x), static_cast<int>(y), threshold, plane, open))
        ++s.occluders, s.depth_sum += d;
    }
  return s;
}

PcfAreaSums pcf_area_reference_plane(const Image& depth, double x, double y, double side, float threshold,
                                     const PlanePcf& plane, bool& open) {
  PcfAreaSums sums;
  for_each_area_texel(depth.width, depth.height, x, y, side, [&](int i, int j, double w) {
    const float d = depth.at(i, j);
    ++sums.touched;
    sums.area += w;
    if (plane_occludes(d, i, j, threshold, plane, open)) sums.occluders += w, sums.depth_sum += w * d;
  });
  return sums;
}

PcfAreaSums pcf_area_reference(const Image& depth, double x, double y, double side, float threshold) {
  PcfAreaSums sums;
  for_each_area_texel(depth.width, depth.height, x, y, side, [&](int i, int j, double w) {
    const float d = depth.at(i, j);
    ++sums.touched;
    sums.area += w;
    if (std::isfinite(d) && d < threshold) sums.occluders += w, sums.depth_sum += w * d;
  });
  return sums;
}

}  // namespace pn

namespace pn {

namespace {

// The four texels around (x, y), each lit unless `occludes(d, tx, ty)`, weighted bilinearly.
template <class Occludes>
double bilinear(const Image& depth, double x, double y, Occludes occludes) {
  if (!std::isfinite(x) || !std::isfinite(y)) return 1.0;
  const double px = x - 0.5, py = y - 0.5;
  const double cx = std::floor(px), cy = std::floor(py);
  const double fx = px - cx, fy = py - cy;
  double visibility = 0.0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const double tx = std::clamp(cx + i, 0.0, depth.width - 1.0), ty = std::clamp(cy + j, 0.0, depth.height - 1.0);
      const float d = depth.at(static_cast<int>(tx), static_cast<int>(ty));
      const bool occluding = std::isfinite(d) && occludes(static_cast<double>(d), tx, ty);
      visibility += (occluding ? 0.0 : 1.0) * (i ? fx : 1.0 - fx) * (j ? fy : 1.0 - fy);
    }
  return visibility;
}

}  // namespace

double pcf_bilinear_reference(const Image& depth, double x, double y, float threshold) {
  return bilinear(depth, x, y, [&](double d, double, double) { return d < threshold; });
}

BilinearPlane pcf_bilinear_reference_plane(const Image& depth, double x, double y, double receiver_depth,
                                           double gradient_u, double gradient_v, double bias, double band) {
  BilinearPlane r;
  const double t0 = receiver_depth - bias;
  r.visibility = bilinear(depth, x, y, [&](double d, double tx, double ty) {
    const double t = receiver_plane_threshold(t0, gradient_u * (tx + 0.5 - x) + gradient_v * (ty + 0.5 - y));
    const double width = band * (std::fabs(t0) + std::fabs(gradient_u) * (std::fabs(tx) + std::fabs(x) + 1.0) +
                                 std::fabs(gradient_v) * (std::fabs(ty) + std::fabs(y) + 1.0));
    if (std::fabs(d - t) <= width) r.open = true;
    return d < t;
  });
  return r;
}

}  // namespace pn
