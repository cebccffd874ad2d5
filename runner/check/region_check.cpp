// Cases of the region check: the literal Steps 1–7 (and the centred option)
// exhaustively over integer and half-integer centres, including outside the
// map, and every integer side 0…2N for N = 2, 3, 8, 13, 64; seeded random
// float regions for N = 1024; NaN / negative / infinite inputs. Bit-exact,
// plus the property that every window is a power of two <= N inside the map.
#include <cmath>
#include <limits>
#include <string>

#include "core/seeded_random.h"
#include "check/module_check.h"
#include "core/query_grid.h"
#include "pass_runners/region_pass.h"
#include "pipeline/pcss_settings.h"
#include "reference/region_reference.h"

namespace pn {

// The pipeline hands RegionMode to pcss_regions.glsl as its int value (regionMode).

namespace {

constexpr int kExhaustiveSizes[] = {2, 3, 8, 13, 64};
constexpr int kRandomSize = 1024;
constexpr int kRandomRegions = 200000;

// 1 where the window is a power of two <= N lying inside the map, else 0.
Image window_validity(const Image& windows, int n) {
  Image valid(windows.width, windows.height);
  for (int y = 0; y < windows.height; ++y) {
    for (int x = 0; x < windows.width; ++x) {
      const int u = static_cast<int>(windows.at(x, y, 0)), v = static_cast<int>(windows.at(x, y, 1));
      const int s = static_cast<int>(windows.at(x, y, 2)), level = static_cast<int>(windows.at(x, y, 3));
      const bool ok = s >= 1 && s <= n && (s & (s - 1)) == 0 && (1 << level) == s && u >= 0 && v >= 0 &&
                      u + s <= n && v + s <= n;
      valid.at(x, y) = ok ? 1.0f : 0.0f;
    }
  }
  return valid;
}

void add_cases(std::vector<CaseResult>& results, const std::string& name, const RegionQuery& pass,
               const std::vector<Query>& queries, int n) {
  const Image input = query_image(queries);
  for (bool centred : {false, true}) {
    const Image observed = pass.run(input, n, centred);
    Image expected(input.width, input.height, 4);
    for (int y = 0; y < input.height; ++y) {
      for (int x = 0; x < input.width; ++x) {
        const float qx = input.at(x, y, 0), qy = input.at(x, y, 1), qs = input.at(x, y, 2);
        const RegionWindow w = centred ? region_centred_reference(qx, qy, qs, n) : region_reference(qx, qy, qs, n);
        expected.at(x, y, 0) = static_cast<float>(w.u);
        expected.at(x, y, 1) = static_cast<float>(w.v);
        expected.at(x, y, 2) = static_cast<float>(w.side);
        expected.at(x, y, 3) = static_cast<float>(w.level);
      }
    }
    const std::string mode = centred ? " centred" : " literal";
    const Tolerance exact = Tolerance::exact();
    results.push_back({name + mode, exact, compare(expected, observed, exact)});
    results.push_back({name + mode + " windows inside the map, power of two <= N", exact,
                       compare(Image(input.width, input.height, 1, 1.0f), window_validity(observed, n), exact)});
  }
}

}  // namespace

std::vector<CaseResult> run_region_check(const CheckEnvironment& env) {
  const RegionQuery pass(env.device, env.tree);
  std::vector<CaseResult> results;
  for (int n : kExhaustiveSizes) {
    // Centres from half a map outside on each side; half-integer centres on the small maps.
    const int lo = -n / 2 - 2, hi = n + n / 2 + 1;
    const float step = n <= 13 ? 0.5f : 1.0f;
    std::vector<Query> queries;
    for (float y = float(lo); y <= float(hi); y += step)
      for (float x = float(lo); x <= float(hi); x += step)
        for (int s = 0; s <= 2 * n; ++s) queries.push_back({x, y, float(s), 0.0f});
    add_cases(results, "N=" + std::to_string(n) + " all centres and sides", pass, queries, n);
  }

  SeededRandom random(0x5eed0003u);
  const float n = static_cast<float>(kRandomSize);
  std::vector<Query> queries;
  for (int k = 0; k < kRandomRegions; ++k)
    queries.push_back({random.uniform_float(-0.25f * n, 1.25f * n), random.uniform_float(-0.25f * n, 1.25f * n),
                       random.uniform_float(0.0f, 2.0f * n), 0.0f});
  add_cases(results, "N=1024 random float regions", pass, queries, kRandomSize);

  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const std::vector<Query> odd{{100.5f, 7.25f, nan, 0},  {100.5f, 7.25f, -3.0f, 0}, {nan, 50.0f, 9.0f, 0},
                               {50.0f, nan, 9.0f, 0},     {inf, 3.0f, 5.0f, 0},      {-inf, -inf, 5.0f, 0},
                               {512.0f, 512.0f, inf, 0}, {1e30f, -1e30f, 1e30f, 0}, {-0.0f, 0.0f, 0.0f, 0}};
  add_cases(results, "N=1024 NaN, negative and infinite inputs", pass, odd, kRandomSize);
  return results;
}

}  // namespace pn
