// Cases of the shadow_map check: each scene's rasterised shadow map (linear
// light depth, shadow_depth.vert/.frag) against a CPU ray cast through every
// texel centre. Away from silhouettes the depths agree to float rounding. On a
// silhouette the rasteriser's fixed-point edge test and the exact ray may
// disagree about a centre that lies (almost) on an edge, and a side face seen
// edge-on (a sliver) interpolates a depth from snapped vertices; there the
// texel must hold a depth within the range the rays through its 3×3
// neighbourhood see, widened by kSliver relative.
#include <algorithm>
#include <cmath>
#include <string>

#include "check/module_check.h"
#include "gl/texture.h"
#include "passes/shadow_map_pass.h"
#include "scene/scene.h"

namespace pn {
namespace {

constexpr double kRelative = 1e-5;  // interpolated linear depth: a few float roundings
constexpr double kSliver = 1e-4;    // extrapolation on edge-on faces from 1/256-texel vertex snapping

bool same_depth(float expected, float observed) {
  if (std::isinf(expected) || std::isinf(observed)) return expected == observed;
  return std::fabs(static_cast<double>(expected) - observed) <= kRelative * std::fabs(static_cast<double>(expected));
}

}  // namespace

std::vector<CaseResult> run_shadow_map_check(const CheckEnvironment& env) {
  const ShadowMapRenderer renderer(env.context, env.tree);
  std::vector<CaseResult> results;
  for (const auto& fixture : fixtures::kScenes) {
    for (int n : {100, 256}) {
      const Scene scene = make_scene(fixture, n);
      const Image observed = read_float_texture(env.context, renderer.render(scene), n, n, 1);
      Image expected(n, n);
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) expected.at(x, y) = ray_cast_light_depth(scene, x, y);
      Image masked_expected = expected, masked_observed = observed, explained(n, n, 1, 1.0f), all_ones(n, n, 1, 1.0f);
      int silhouette = 0;
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          if (same_depth(expected.at(x, y), observed.at(x, y))) continue;
          ++silhouette;
          double lo = INFINITY, hi = -INFINITY;
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
              if (x + dx >= 0 && x + dx < n && y + dy >= 0 && y + dy < n)
                lo = std::min(lo, double(expected.at(x + dx, y + dy))), hi = std::max(hi, double(expected.at(x + dx, y + dy)));
          const double o = observed.at(x, y);
          const bool within = std::isinf(o) ? std::isinf(hi) : (o >= lo * (1 - kSliver) && o <= hi * (1 + kSliver));
          explained.at(x, y) = within ? 1.0f : 0.0f;
          masked_expected.at(x, y) = masked_observed.at(x, y) = 0.0f;
        }
      const std::string name = std::string(fixture.name) + " " + std::to_string(n) + "x" + std::to_string(n);
      const Tolerance depth_tol = Tolerance::relative(kRelative);
      results.push_back({name + ": linear light depth vs ray cast, off silhouettes (" + std::to_string(silhouette) +
                             " silhouette texels)",
                         depth_tol, compare(masked_expected, masked_observed, depth_tol)});
      results.push_back({name + ": every silhouette texel lies within its 3x3 rays' depths", Tolerance::exact(),
                         compare(all_ones, explained, Tolerance::exact())});
    }
  }
  return results;
}

}  // namespace pn
