// Cases of the light_model check: the GLSL widths equal runner/scene/light_model.h
// over a grid of receiver and blocker depths for several lights (area lights on
// perspective maps, directional lights on orthographic ones) (relative
// float rounding, the grid keeping dP / z >= 1.01 so the difference does not
// cancel), and degenerate inputs give exactly 0 where the definition says 0; pnLightProject of
// world points spread unevenly in x and z (issue 54: u and v swapped, or the + 1/2 dropped, passed
// every check) against the projection in double.
#include <cmath>
#include <limits>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "check/module_check.h"
#include "core/format.h"
#include "core/query_grid.h"
#include "core/seeded_random.h"
#include "pass_runners/light_depth_query_pass.h"
#include "pass_runners/light_model_query_pass.h"
#include "scene/light_model.h"

namespace pn {

namespace {

constexpr double kFloatEpsilon = 1.1920929e-7;

// NDC z of the view-space depth `depth` (> 0, along -z) through `projection`, in double.
double ndc_z(const glm::mat4& projection, double depth) {
  const double z = -depth;
  return (projection[2][2] * z + projection[3][2]) / (projection[2][3] * z + projection[3][3]);
}

// The depth in [lo, hi] whose NDC z is `ndc` (NDC z monotonic in depth): bisection in double.
double depth_of_ndc(const glm::mat4& projection, double ndc, double lo, double hi) {
  const bool increasing = ndc_z(projection, hi) > ndc_z(projection, lo);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((ndc_z(projection, mid) < ndc) == increasing ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

struct DepthProjection {
  const char* name;
  glm::mat4 matrix;
  double near_plane, far_plane;  // the depths the buffer holds
};

// A [0, 1]-clip perspective with reversed Z (near -> 1, far -> 0; far = +Inf: infinite).
glm::mat4 reversed_z(double fov, double near_plane, double far_plane) {
  glm::mat4 m(0.0f);
  const double f = 1.0 / std::tan(0.5 * fov);
  m[0][0] = m[1][1] = static_cast<float>(f);
  m[2][3] = -1.0f;
  const bool infinite = std::isinf(far_plane);
  m[2][2] = infinite ? 0.0f : static_cast<float>(near_plane / (far_plane - near_plane));
  m[3][2] = infinite ? static_cast<float>(near_plane) : static_cast<float>(far_plane * near_plane / (far_plane - near_plane));
  return m;
}

void depth_buffer_cases(const CheckEnvironment& env, std::vector<CaseResult>& results) {
  const LightDepthQueryPass gpu(env.device, env.tree);
  const DepthProjection projections[] = {
      {"perspective 90 deg, near 1, far 100", glm::perspective(1.5707963f, 1.0f, 1.0f, 100.0f), 1.0, 100.0},
      {"perspective 60 deg, near 0.1, far 1000", glm::perspective(1.0471976f, 1.0f, 0.1f, 1000.0f), 0.1, 1000.0},
      {"orthographic, near 1, far 400", glm::ortho(-10.0f, 10.0f, -10.0f, 10.0f, 1.0f, 400.0f), 1.0, 400.0},
      {"reversed-Z perspective, near 0.5, far 200", reversed_z(1.2, 0.5, 200.0), 0.5, 200.0},
      {"reversed-Z infinite perspective, near 0.5 (depths to 1e4)", reversed_z(1.2, 0.5, INFINITY), 0.5, 1e4},
  };
  for (const DepthProjection& p : projections)
    for (const bool zero_to_one : {false, true}) {
      // The values a float32 depth buffer holds for depths spread from near to far.
      std::vector<Query> queries;
      std::vector<double> ndc;
      for (int i = 0; i <= 400; ++i) {
        const double depth = p.near_plane * std::pow(p.far_plane / p.near_plane, i / 400.0);
        const double n = ndc_z(p.matrix, depth);
        const float value = static_cast<float>(zero_to_one ? n : 0.5 * n + 0.5);
        if (!(value >= 0.0f && value <= 1.0f)) continue;
        queries.push_back({value, 0, 0, 0});
        ndc.push_back(zero_to_one ? static_cast<double>(value) : 2.0 * static_cast<double>(value) - 1.0);
      }
      const Image input = query_image(queries);
      const Image observed = gpu.run(p.matrix, input);
      Image expected(input.width, input.height, 1), got(input.width, input.height, 1);
      // Float rounding of (b - z d) / (a - z c) with the matrix's float entries: a few ulps of each
      // operand, amplified where numerator or denominator cancel (the far plane of a [-1, 1] clip range).
      double condition = 1.0;
      const glm::mat4& m = p.matrix;
      for (size_t k = 0; k < queries.size(); ++k) {
        const double z = ndc[k];
        const double lo = p.near_plane * 0.5, hi = p.far_plane * 2.0;
        expected.at(static_cast<int>(k) % input.width, static_cast<int>(k) / input.width) =
            static_cast<float>(depth_of_ndc(m, z, lo, std::isinf(hi) ? 1e9 : hi));
        got.at(static_cast<int>(k) % input.width, static_cast<int>(k) / input.width) =
            observed.at(static_cast<int>(k) % input.width, static_cast<int>(k) / input.width, zero_to_one ? 1 : 0);
        const double numerator = m[3][2] - z * m[3][3], denominator = m[2][2] - z * m[2][3];
        condition = std::max(condition, (std::abs(m[3][2]) + std::abs(z * m[3][3])) / std::abs(numerator) +
                                            (std::abs(m[2][2]) + std::abs(z * m[2][3])) / std::abs(denominator));
      }
      const Tolerance tolerance = Tolerance::relative(8.0 * kFloatEpsilon * condition);
      results.push_back({std::string("depth buffer -> linear depth, ") + p.name +
                             (zero_to_one ? ", [0, 1] clip" : ", [-1, 1] clip") + ", " +
                             std::to_string(queries.size()) + " float32 values vs the depth projecting to each",
                         tolerance, compare(expected, got, tolerance)});
    }
}

// pnLightProject of world points: (u, v) = (clip.xy / clip.w · 1/2 + 1/2) · mapSize, the
// projection computed in double from the float matrices. A light off the axes, looking down at a
// slant, and points spread unevenly in x and z: u and v differ everywhere.
void light_project_cases(const CheckEnvironment& env, std::vector<CaseResult>& results) {
  const LightDepthQueryPass gpu(env.device, env.tree);
  const glm::mat4 view = glm::lookAt(glm::vec3(1.5f, 20.0f, -2.5f), glm::vec3(0.3f, 0.0f, 0.7f), glm::vec3(0.0f, 0.0f, -1.0f));
  const glm::mat4 projection = glm::perspective(1.0471976f, 1.0f, 9.0f, 40.0f);
  const float map_size = 512.0f;
  SeededRandom random(0x5eed0054u);
  std::vector<Query> queries;
  for (int k = 0; k < 256; ++k)
    queries.push_back({0.5f, random.uniform_float(-7.0f, 5.0f), random.uniform_float(0.0f, 3.0f),
                       random.uniform_float(-2.0f, 9.0f)});
  const Image input = query_image(queries);
  const Image observed = gpu.run(projection, input, view, map_size);
  Image expected_u(input.width, input.height, 1), expected_v(input.width, input.height, 1);
  Image got_u(input.width, input.height, 1), got_v(input.width, input.height, 1);
  for (size_t k = 0; k < queries.size(); ++k) {
    double world[4] = {queries[k][1], queries[k][2], queries[k][3], 1.0}, eye[4] = {}, clip[4] = {};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) eye[r] += static_cast<double>(view[c][r]) * world[c];
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) clip[r] += static_cast<double>(projection[c][r]) * eye[c];
    const int x = static_cast<int>(k) % input.width, y = static_cast<int>(k) / input.width;
    expected_u.at(x, y) = static_cast<float>((clip[0] / clip[3] * 0.5 + 0.5) * map_size);
    expected_v.at(x, y) = static_cast<float>((clip[1] / clip[3] * 0.5 + 0.5) * map_size);
    got_u.at(x, y) = observed.at(x, y, 2), got_v.at(x, y) = observed.at(x, y, 3);
  }
  // Float rounding of two matrix products and a divide, in texels: well under 64 ulps of the map's size.
  const Tolerance tolerance = Tolerance::absolute(64.0 * kFloatEpsilon * map_size);
  for (const auto& [axis, expected, got] : {std::tuple{"u", &expected_u, &got_u}, {"v", &expected_v, &got_v}})
    results.push_back({std::string("pnLightProject ") + axis + " of 256 world points, a slanted light off the axes, " +
                           "512 texels, vs the projection in double",
                       tolerance, compare(*expected, *got, tolerance)});
}

}  // namespace

std::vector<CaseResult> run_light_model_check(const CheckEnvironment& env) {
  const LightModelQueryPass gpu(env.device, env.tree);
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
  depth_buffer_cases(env, results);
  light_project_cases(env, results);
  return results;
}

}  // namespace pn
