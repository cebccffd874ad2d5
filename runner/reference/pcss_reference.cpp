#include "reference/pcss_reference.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "receiver_plane.h"
#include "reference/depth_pyramid_reference.h"
#include "reference/pcf_reference.h"
#include "reference/receiver_plane_reference.h"

namespace pn {
namespace {

// The G-buffer entry (u, v, d, valid) at (x, y); invalid outside the screen.
Entry4 entry_at(const Image& gbuffer, int x, int y) {
  if (x < 0 || y < 0 || x >= gbuffer.width || y >= gbuffer.height) return {0.0, 0.0, 0.0, 0.0};
  return {gbuffer.at(x, y, 0), gbuffer.at(x, y, 1), gbuffer.at(x, y, 2), gbuffer.at(x, y, 3)};
}

// The one-sided steps float arithmetic could take: the chosen one, and the other when their |Δd| lie
// within 1e-5 of a tie (on a plane sampled evenly they always do, and both give the same plane).
std::vector<Step3> candidate_steps(const Entry4& centre, const Entry4& minus, const Entry4& plus) {
  std::vector<Step3> out{receiver_plane_step(centre, minus, plus)};
  if (minus[3] == 0.0 || plus[3] == 0.0) return out;
  const double a = std::fabs(plus[2] - centre[2]), b = std::fabs(centre[2] - minus[2]);
  if (std::fabs(a - b) <= 1e-5 * (a + b + std::fabs(centre[2]))) {
    out.push_back({plus[0] - centre[0], plus[1] - centre[1], plus[2] - centre[2]});
    out.push_back({centre[0] - minus[0], centre[1] - minus[1], centre[2] - minus[2]});
  }
  return out;
}

// The pixel's receiver plane, and whether float arithmetic could decide it otherwise: the
// candidate steps' planes differ by more than 1e-4 of the slope, the steps lie within 0.1 % of the
// parallel bound, or the unclamped slope within 0.01 % of the clamp (whether it clamps; a clamped
// plane's own rounding is the decisions' margin's).
std::array<double, 2> plane_at(const Image& gbuffer, int px, int py, double max_slope, bool& unsure) {
  const Entry4 c = entry_at(gbuffer, px, py);
  const Entry4 left = entry_at(gbuffer, px - 1, py), right = entry_at(gbuffer, px + 1, py);
  const Entry4 below = entry_at(gbuffer, px, py - 1), above = entry_at(gbuffer, px, py + 1);
  const Step3 a = receiver_plane_step(c, left, right), b = receiver_plane_step(c, below, above);
  const std::array<double, 2> g = receiver_plane_gradient(a, b, max_slope);
  const double slope = std::hypot(g[0], g[1]);
  unsure = false;
  for (const Step3& sa : candidate_steps(c, left, right))
    for (const Step3& sb : candidate_steps(c, below, above)) {
      const std::array<double, 2> other = receiver_plane_gradient(sa, sb, max_slope);
      if (std::hypot(other[0] - g[0], other[1] - g[1]) > 1e-4 * slope + 1e-12) unsure = true;
      const double det = sa[0] * sb[1] - sa[1] * sb[0];
      const double bound = PN_RECEIVER_PLANE_MIN_SINE * std::hypot(sa[0], sa[1]) * std::hypot(sb[0], sb[1]);
      if (std::fabs(std::fabs(det) - bound) <= 1e-3 * bound) unsure = true;
    }
  const std::array<double, 2> unclamped = receiver_plane_gradient(a, b, INFINITY);
  if (std::fabs(std::hypot(unclamped[0], unclamped[1]) - max_slope) <= 1e-4 * max_slope) unsure = true;
  return g;
}

}  // namespace

PcssReference exact_pcss_reference(const Image& shadow_map, const Image& gbuffer, const LightModel& light, double bias,
                                   double filter_scale, double margin, double receiver_plane_tan) {
  const int n = shadow_map.width;
  PcssReference out{Image(gbuffer.width, gbuffer.height, 1, 1.0f), Image(gbuffer.width, gbuffer.height, 1, 0.0f)};
  for (int py = 0; py < gbuffer.height; ++py)
    for (int px = 0; px < gbuffer.width; ++px) {
      const double u = gbuffer.at(px, py, 0), v = gbuffer.at(px, py, 1), d = gbuffer.at(px, py, 2);
      if (gbuffer.at(px, py, 3) == 0.0f || std::isnan(d)) continue;
      const double t0 = d - bias;
      bool unsure = false;
      const std::array<double, 2> g =
          receiver_plane_tan > 0 ? plane_at(gbuffer, px, py, receiver_plane_tan * light.texel_world_at(d), unsure)
                                 : std::array<double, 2>{0.0, 0.0};
      if (unsure) out.ambiguous.at(px, py) = 1.0f;
      double depth_margin = INFINITY;
      const auto scan = [&](const Rect& r, double& occluders, double& sum) {
        occluders = sum = 0.0;
        for (int y = r.y; y < r.y + r.height; ++y)
          for (int x = r.x; x < r.x + r.width; ++x) {
            const double z = sanitize_depth(shadow_map.at(x, y));
            const double t = receiver_plane_threshold(t0, g[0] * (x + 0.5 - u) + g[1] * (y + 0.5 - v));
            if (z < t) occluders += 1.0, sum += z;
            if (std::isfinite(z)) depth_margin = std::min(depth_margin, std::fabs(z - t) / d);
          }
      };
      double m1 = 1.0, m2 = 1.0, occluders = 0.0, sum = 0.0;
      scan(pcss_square(u, v, light.search_width_texels(d), n, &m1), occluders, sum);
      if (occluders == 0.0) {
        if (std::min(m1, depth_margin) < margin) out.ambiguous.at(px, py) = 1.0f;
        continue;
      }
      const double blocker = sum / occluders;
      const Rect filter = pcss_square(u, v, filter_scale * light.penumbra_texels(d, blocker), n, &m2);
      scan(filter, occluders, sum);
      const double texels = static_cast<double>(filter.width) * filter.height;
      out.visibility.at(px, py) = static_cast<float>(texels > 0 ? 1.0 - occluders / texels : 1.0);
      if (std::min({m1, m2, depth_margin}) < margin) out.ambiguous.at(px, py) = 1.0f;
    }
  return out;
}

PcssReference exact_pcss_area_reference(const Image& shadow_map, const Image& gbuffer, const LightModel& light,
                                        float bias, double filter_scale, double margin) {
  PcssReference out{Image(gbuffer.width, gbuffer.height, 1, 1.0f), Image(gbuffer.width, gbuffer.height, 1, 0.0f)};
  for (int py = 0; py < gbuffer.height; ++py)
    for (int px = 0; px < gbuffer.width; ++px) {
      const float u = gbuffer.at(px, py, 0), v = gbuffer.at(px, py, 1), d = gbuffer.at(px, py, 2);
      if (gbuffer.at(px, py, 3) == 0.0f || std::isnan(d)) continue;
      const float t = d - bias;  // the float threshold the module forms
      const double side = light.search_width_texels(d);
      const PcfAreaSums search = pcf_area_reference(shadow_map, u, v, side, t);
      // Blockers or none within `margin` of the square's edges: rounding may decide either way.
      if (search.occluders <= margin * (side + 2.0) * 4.0 &&
          pcf_area_reference(shadow_map, u, v, side + 2.0 * margin, t).occluders > 0.0)
        out.ambiguous.at(px, py) = 1.0f;
      if (search.occluders == 0.0) continue;
      const double blocker = search.depth_sum / search.occluders;
      const PcfAreaSums filter =
          pcf_area_reference(shadow_map, u, v, filter_scale * light.penumbra_texels(d, blocker), t);
      out.visibility.at(px, py) = static_cast<float>(filter.area > 0.0 ? 1.0 - filter.occluders / filter.area : 1.0);
    }
  return out;
}

PcssReference pcf_plane_reference(const Image& shadow_map, const Image& gbuffer, const LightModel& light, double bias,
                                  double margin, double receiver_plane_tan) {
  PcssReference out{Image(gbuffer.width, gbuffer.height, 1, 1.0f), Image(gbuffer.width, gbuffer.height, 1, 0.0f)};
  for (int py = 0; py < gbuffer.height; ++py)
    for (int px = 0; px < gbuffer.width; ++px) {
      const double d = gbuffer.at(px, py, 2);
      if (gbuffer.at(px, py, 3) == 0.0f) continue;
      bool unsure = false;
      const std::array<double, 2> g =
          receiver_plane_tan > 0 ? plane_at(gbuffer, px, py, receiver_plane_tan * light.texel_world_at(d), unsure)
                                 : std::array<double, 2>{0.0, 0.0};
      const BilinearPlane r =
          pcf_bilinear_reference_plane(shadow_map, gbuffer.at(px, py, 0), gbuffer.at(px, py, 1), d, g[0], g[1], bias, margin);
      out.visibility.at(px, py) = static_cast<float>(r.visibility);
      if (unsure || r.open) out.ambiguous.at(px, py) = 1.0f;
    }
  return out;
}

}  // namespace pn
