#include "reference/pcss_reference.h"

#include <algorithm>
#include <cmath>

#include "reference/depth_pyramid_reference.h"

namespace pn {

PcssReference exact_pcss_reference(const Image& shadow_map, const Image& gbuffer, const LightModel& light, double bias,
                                   double filter_scale, double margin) {
  const int n = shadow_map.width;
  PcssReference out{Image(gbuffer.width, gbuffer.height, 1, 1.0f), Image(gbuffer.width, gbuffer.height, 1, 0.0f)};
  for (int py = 0; py < gbuffer.height; ++py)
    for (int px = 0; px < gbuffer.width; ++px) {
      const double u = gbuffer.at(px, py, 0), v = gbuffer.at(px, py, 1), d = gbuffer.at(px, py, 2);
      if (gbuffer.at(px, py, 3) == 0.0f || std::isnan(d)) continue;
      const double t = d - bias;
      double depth_margin = INFINITY;
      const auto scan = [&](const Rect& r, double& occluders, double& sum) {
        occluders = sum = 0.0;
        for (int y = r.y; y < r.y + r.height; ++y)
          for (int x = r.x; x < r.x + r.width; ++x) {
            const double z = sanitize_depth(shadow_map.at(x, y));
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

}  // namespace pn
