// Cases of the depth_pyramid check: every level of every fixture at N = 2, 3, 64,
// 100, 257, 512 against the window scan (min/max bit-exact, mean within
// float rounding), and the any-square query against a scan of the square —
// all squares on small maps, seeded random ones on large maps, squares above
// a capped maximum level, and out-of-range queries that the module clamps.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <memory>
#include <string>

#include "core/seeded_random.h"
#include "check/module_check.h"
#include "core/query_grid.h"
#include "fixture_images/texture_fixture.h"
#include "pass_runners/depth_pyramid_pass.h"
#include "reference/depth_pyramid_reference.h"

namespace pn {
namespace {

constexpr int kLevelSizes[] = {2, 3, 64, 100, 257, 512};
constexpr int kAllSquaresSizes[] = {2, 3, 8, 13};
constexpr int kRandomSquaresSizes[] = {64, 100, 257, 512};
constexpr int kRandomSquares = 1000;

std::string label(const char* fixture, int n) { return std::string(fixture) + " " + std::to_string(n) + "x" + std::to_string(n); }

// The module's documented clamp of a square query: side into [1, N], origin so the square fits.
Query clamped(Query q, int n) {
  const int s = std::clamp(static_cast<int>(q[2]), 1, n);
  q[2] = static_cast<float>(s);
  for (int i = 0; i < 2; ++i) q[static_cast<size_t>(i)] = static_cast<float>(std::clamp(static_cast<int>(q[static_cast<size_t>(i)]), 0, n - s));
  return q;
}

// Queries and their expected (min, max), scanned once and reused for every pyramid asked.
struct SquareQueries {
  Image input;
  Image expected;
};

SquareQueries square_queries(const Image& map, const std::vector<Query>& queries) {
  const Image depth = sanitized_depths(map);
  SquareQueries q{query_image(queries), {}};
  q.expected = Image(q.input.width, q.input.height, 2);
  for (int y = 0; y < q.input.height; ++y) {
    for (int x = 0; x < q.input.width; ++x) {
      const Query c = clamped({q.input.at(x, y, 0), q.input.at(x, y, 1), q.input.at(x, y, 2), 0.0f}, map.width);
      const auto [lo, hi] = square_min_max(depth, static_cast<int>(c[0]), static_cast<int>(c[1]), static_cast<int>(c[2]));
      q.expected.at(x, y, 0) = lo;
      q.expected.at(x, y, 1) = hi;
    }
  }
  return q;
}

CaseResult square_case(const std::string& name, const DepthPyramidQuery& query, const DepthPyramid& pyramid,
                       const SquareQueries& queries) {
  const Image observed = channels_of(query.run(pyramid, queries.input), 0, 2);
  const Tolerance exact = Tolerance::exact();
  return {name, exact, compare(queries.expected, observed, exact)};
}

}  // namespace

std::vector<CaseResult> run_depth_pyramid_check(const CheckEnvironment& env) {
  const DepthPyramidBuilder builder(env.device, env.tree);
  const DepthPyramidQuery query(env.device, env.tree);
  std::vector<CaseResult> results;

  for (const auto& fixture : check_texture_fixtures(env)) {
    for (int n : kLevelSizes) {
      const Image map = generate_fixture(fixture, n, n);
      const DepthPyramid pyramid = builder.build(*env.device.upload(map), n, n, 31);
      const float m = largest_finite_magnitude(map, FLT_MIN);
      for (int level = 0; level < pyramid.levels; ++level) {
        const Image observed = read_pyramid_level(env.device, pyramid, level);
        const Image expected = pyramid_level_reference(map, level);
        const std::string name = label(fixture.name, n) + " level " + std::to_string(level);
        const Tolerance exact = Tolerance::exact();
        results.push_back({name + " min/max", exact, compare(channels_of(expected, 0, 2), channels_of(observed, 0, 2), exact)});
        // Mean of means: each level adds three float roundings of values <= 4M, then
        // scales by 1/4 exactly; 2(i+1) ulps of the largest |depth| covers them and the
        // reference's own rounding to float.
        const Tolerance mean_tol = Tolerance::absolute(2.0 * (level + 1) * FLT_EPSILON * m);
        results.push_back({name + " mean", mean_tol, compare(channels_of(expected, 2, 1), channels_of(observed, 2, 1), mean_tol)});
      }
    }
  }

  for (const char* name : {"noise", "nonfinite", "checker"}) {
    const auto& fixture = find_fixture(name);
    for (int n : kAllSquaresSizes) {
      const Image map = generate_fixture(fixture, n, n);
      const DepthPyramid pyramid = builder.build(*env.device.upload(map), n, n, 31);
      std::vector<Query> queries;
      for (int s = 1; s <= n; ++s)
        for (int v = 0; v + s <= n; ++v)
          for (int u = 0; u + s <= n; ++u) queries.push_back({float(u), float(v), float(s), 0.0f});
      results.push_back(square_case(label(name, n) + " all squares", query, pyramid, square_queries(map, queries)));
    }
  }

  SeededRandom random(0x9e3779b9u);
  for (const char* name : {"noise", "step_edge", "nonfinite"}) {
    const auto& fixture = find_fixture(name);
    for (int n : kRandomSquaresSizes) {
      const Image map = generate_fixture(fixture, n, n);
      const std::unique_ptr<DeviceTexture> map_texture = env.device.upload(map);
      std::vector<Query> queries;
      for (int k = 0; k < kRandomSquares; ++k) {
        const int s = random.uniform_int(1, n);
        queries.push_back({float(random.uniform_int(0, n - s)), float(random.uniform_int(0, n - s)), float(s), 0.0f});
      }
      const SquareQueries random_squares = square_queries(map, queries);
      const DepthPyramid full = builder.build(*map_texture, n, n, 31);
      results.push_back(square_case(label(name, n) + " random squares", query, full, random_squares));
      // A capped pyramid (levels 0–2) answers large squares with more fetches.
      const DepthPyramid capped = builder.build(*map_texture, n, n, 2);
      results.push_back(square_case(label(name, n) + " random squares, max level 2", query, capped, random_squares));
      // Out-of-range queries are clamped, never read outside the pyramid.
      const std::vector<Query> outside{{-5, -5, 3, 0}, {float(n), float(n), 2, 0}, {0, 0, float(2 * n), 0},
                                       {1, 1, 0, 0},   {3, 2, -4, 0},             {float(n - 1), 0, float(n), 0}};
      results.push_back(
          square_case(label(name, n) + " out-of-range squares (clamped)", query, full, square_queries(map, outside)));
    }
  }
  return results;
}

}  // namespace pn
