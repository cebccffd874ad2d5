// Cases of the region check: the literal Steps 1–7 (and the centred option)
// exhaustively over integer and half-integer centres, including outside the
// map, and every integer side 0…2N for N = 2, 3, 8, 13, 64; seeded random
// float regions for N = 1024; NaN / negative / infinite inputs. Bit-exact,
// plus the property that every window is a power of two <= N inside the map.
// The area-weighted region (pnRegionArea, pnRegionAreaSpan, pnRegionAreaOver, pnRegionAreaOfRect;
// issue 54: their min/max and dropped-term mutants passed region's own check) at random float
// centres and sides against the overlap of the continuous square with texels, in double.
#include <algorithm>
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

// The length of [a0, a1) ∩ [b0, b1].
double overlap(double a0, double a1, double b0, double b1) { return std::max(0.0, std::min(a1, b1) - std::max(a0, b0)); }

void area_cases(std::vector<CaseResult>& results, const RegionQuery& pass, int n, SeededRandom& random) {
  std::vector<Query> queries;
  for (int k = 0; k < 4096; ++k)
    queries.push_back({random.uniform_float(-0.5f * n, 1.5f * n), random.uniform_float(-0.5f * n, 1.5f * n),
                       random.uniform_float(0.25f, 1.5f * n), static_cast<float>(random.uniform_int(-2, n + 1))});
  const Image input = query_image(queries);
  const Image observed = pass.run_areas(input, n);
  Image expected(input.width, input.height, 4);
  for (size_t k = 0; k < queries.size(); ++k) {
    const int x = static_cast<int>(k) % input.width, y = static_cast<int>(k) / input.width;
    const Query& q = queries[k];
    // The square of side clamp(s, 1, 4N) about the centre, clipped to the map [0, N]² (region.glsl's
    // pnRegionArea), its bounds per axis.
    const double half = 0.5 * std::clamp(static_cast<double>(q[2]), 1.0, 4.0 * n);
    double lo[2], hi[2];
    for (int a = 0; a < 2; ++a) {
      lo[a] = std::clamp(q[a] - half, 0.0, static_cast<double>(n));
      hi[a] = std::clamp(q[a] + half, lo[a], static_cast<double>(n));
    }
    const double t = q[3];
    expected.at(x, y, 0) = static_cast<float>(overlap(t, t + 1, lo[0], hi[0]));
    expected.at(x, y, 1) = static_cast<float>(overlap(t, t + 1, lo[1], hi[1]));
    expected.at(x, y, 2) = static_cast<float>(overlap(t, t + 3, lo[0], hi[0]) * overlap(t, t + 2, lo[1], hi[1]));
    const double fx = std::floor(q[0]), fy = std::floor(q[1]);
    expected.at(x, y, 3) = static_cast<float>(overlap(fx, fx + 4, t, t + 5) * overlap(fy, fy + 4, t, t + 3));
  }
  // Float bounds within an ulp of N each, a product of two spans: 16 ulps of N².
  const Tolerance tolerance = Tolerance::absolute(16.0 * std::ldexp(1.0, -23) * n * n);
  results.push_back({"N=" + std::to_string(n) + " area-weighted regions (pnRegionArea, its spans along x and y, its "
                         "overlap with 3x2 texels, pnRegionAreaOfRect's with 4x4): 4096 random float centres and sides "
                         "vs the continuous square's overlaps in double",
                     tolerance, compare(expected, observed, tolerance)});
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
  for (int area_n : {13, 64}) area_cases(results, pass, area_n, random);
  return results;
}

}  // namespace pn
