// Cases of the light_model check: the GLSL widths equal runner/scene/light_model.h
// over a grid of receiver and blocker depths for several lights (area lights on
// perspective maps, directional lights on orthographic ones) (relative
// float rounding, the grid keeping dP / z >= 1.01 so the difference does not
// cancel), and degenerate inputs give exactly 0 where the definition says 0.
#include <cmath>
#include <limits>
#include <string>

#include "check/module_check.h"
#include "core/format.h"
#include "core/query_grid.h"
#include "passes/light_model_query_pass.h"
#include "scene/light_model.h"

namespace pn {

std::vector<CaseResult> run_light_model_check(const CheckEnvironment& env) {
  const LightModelQueryPass gpu(env.context, env.tree);
  std::vector<CaseResult> results;
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  // Area lights (perspective maps), then directional lights on orthographic maps: the sun
  // (0.53 degrees: S = 2 tan(0.265 deg)) on a fine and a coarse cascade, a wider sun, a point sun.
  const double sun = 2.0 * std::tan(0.5 * 0.53 * 3.14159265358979 / 180.0);
  for (LightModel light : {LightModel{2.0, 1.0, 100.0, 1.5707963267948966, 1024},
                           LightModel{0.5, 0.1, 50.0, 0.8, 512}, LightModel{0.0, 1.0, 100.0, 1.0, 1024},
                           LightModel{10.0, 2.0, 500.0, 2.0, 2048}, LightModel{0.0, 1.0, 400.0, 0.0, 1024, sun, 0.02},
                           LightModel{0.0, 3.0, 600.0, 0.0, 2048, sun, 0.7}, LightModel{0.0, 1.0, 400.0, 0.0, 512, 4 * sun, 0.1},
                           LightModel{0.0, 1.0, 400.0, 0.0, 1024, 0.0, 0.05}}) {
    std::vector<Query> regular, degenerate;
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 40; ++j) {
        const float receiver = static_cast<float>(light.near_plane * std::pow(1.25, i));
        const float blocker = static_cast<float>(light.near_plane * std::pow(1.25, j));
        if (receiver >= blocker * 1.01f) regular.push_back({receiver, blocker, 0, 0});
      }
    const float n = static_cast<float>(light.near_plane);
    degenerate = {{5 * n, 5 * n, 0, 0}, {5 * n, 6 * n, 0, 0}, {0.5f * n, 0.25f * n, 0, 0}, {5 * n, 0.5f * n, 0, 0},
                  {nan, n, 0, 0},       {5 * n, nan, 0, 0},   {inf, 2 * n, 0, 0},          {-3, -4, 0, 0}};
    for (const auto& [queries, is_regular] : {std::pair{regular, true}, std::pair{degenerate, false}}) {
      const Image input = query_image(queries);
      const Image observed = gpu.run(light, input);
      Image expected(input.width, input.height, 4);
      for (int y = 0; y < input.height; ++y)
        for (int x = 0; x < input.width; ++x) {
          const double r = input.at(x, y, 0), b = input.at(x, y, 1);
          expected.at(x, y, 0) = static_cast<float>(light.blocker_window_texels(r, b));
          expected.at(x, y, 1) = static_cast<float>(light.search_width_texels(r));
          expected.at(x, y, 2) = static_cast<float>(light.penumbra_world(r, b));
          expected.at(x, y, 3) = static_cast<float>(light.penumbra_texels(r, b));
        }
      const std::string name =
          light.orthographic()
              ? "directional light, spread " + format_number("%.3g", light.spread) + ", texel " +
                    format_number("%g", light.texel_world) + ", near " + format_number("%g", light.near_plane) + ", N " +
                    std::to_string(light.map_size)
              : "light width " + format_number("%g", light.width) + ", near " + format_number("%g", light.near_plane) +
                    ", fov " + format_number("%.3g", light.fov_radians) + ", N " + std::to_string(light.map_size);
      // A dozen float operations, |dP - z| >= 1 % of dP: 64 ulps relative. Relative
      // to an expected 0 (the degenerate widths), any non-zero result fails.
      const Tolerance tolerance = Tolerance::relative(64.0 * 1.1920929e-7);
      results.push_back({name + (is_regular ? ": widths over receiver x blocker depths"
                                            : ": degenerate inputs (widths that must be 0 are exactly 0)"),
                         tolerance, compare(expected, observed, tolerance)});
    }
  }
  return results;
}

}  // namespace pn
