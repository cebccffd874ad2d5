// Cases of the summed_area check (the depth-sum table's half; the moments
// tables' cases: summed_area_moments_check.cpp): glsl/summed_area.glsl's table, built by
// passes/summed_area_build.comp and read by passes/summed_area_query.comp,
// against summed_area_reference (every rectangle summed texel by texel — the
// raw depths in double, the fixed-point values in 64-bit integers; never a
// table on the CPU). Every fixture at 1×1, 3×5, 17×9, 100×37, 257² and 1024²,
// each in four depth ranges:
//   "light depth 40 v": linear depth 0..40, +Inf ("empty") where v >= 0.95;
//   "depth 1000 + v": a large offset, where float prefix sums would lose
//     about 2^-24 of the prefix (64 units at 1024²) to rounding;
//   "depth 40 v - 20": signed depths (two's complement values, prefix sums
//     crossing zero);
//   "depth 1000 + v, F 40": the pass compiled with 40 fraction bits, so that
//     the prefix sums wrap past 2^64 many times over (2^70 at 1024²).
// (v the fixture's value; NaN and ±Inf texels of the NaN/Inf fixture stay as
// they are.) Rectangles: on maps of up to 200 texels every rectangle with
// corners in [-1, N+1] × [-1, M+1] (inside, straddling, outside, empty, 1×1,
// the whole map), plus huge and negative-size ones; on larger maps 1×1 at the
// corners and centre, the whole map, covering it, straddling each edge and
// corner, wholly outside on each side, empty, whole rows and columns, and
// seeded random rectangles inside and across the edges (24 of each; 12 at
// 1024², where the direct sums dominate the check's time).
// Two cases per map and range:
//   fixed point — the 64-bit sum (as three exact 24/24/16-bit digits), the
//     finite count and the texels covered must equal the reference EXACTLY
//     (modulo 2^64 for the sum: that identity holds however the prefixes wrap);
//   float — the depth sum and the mean against the raw depths in double, each
//     query within its own derived bound (summed_area_sum_bound: 2^-(F+1) per
//     finite depth below 2^(23-F) for the quantisation, 2u + u² relative for
//     the one conversion to float, u for the reference's rounding). Queries
//     whose fixed sum does not fit in 63 bits (only at F 40) are left out of
//     it, and counted in the case's name.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "check/summed_area_check.h"
#include "core/error.h"
#include "fixture_images/texture_fixture.h"
#include "gl/texture.h"
#include "pass_runners/summed_area_pass.h"
#include "reference/summed_area_reference.h"

namespace pn {
namespace {

constexpr fixtures::FixtureSize kSizes[] = {{1, 1}, {3, 5}, {17, 9}, {100, 37}, {257, 257}, {1024, 1024}};
constexpr int kWrapFractionBits = 40;

struct Range {
  const char* name;
  int fraction_bits;
  float (*depth)(float v);  // finite fixture values only
};

const Range kRanges[] = {
    {"light depth 40 v, +Inf where v >= 0.95", kSummedAreaFractionBits,
     [](float v) { return v >= 0.95f ? std::numeric_limits<float>::infinity() : 40.0f * v; }},
    {"depth 1000 + v", kSummedAreaFractionBits, [](float v) { return 1000.0f + v; }},
    {"depth 40 v - 20 (signed)", kSummedAreaFractionBits, [](float v) { return 40.0f * v - 20.0f; }},
    {"depth 1000 + v, F 40 (prefix sums wrap past 2^64)", kWrapFractionBits, [](float v) { return 1000.0f + v; }},
};

Image in_range(const Image& fixture, const Range& range) {
  Image out = fixture;
  for (float& d : out.texels)
    if (std::isfinite(d)) d = range.depth(d);
  return out;
}

std::vector<Rect> rects_for(int w, int h) {
  std::vector<Rect> out;
  const auto add = [&out](int x, int y, int rw, int rh) { out.push_back({x, y, rw, rh}); };
  if (w * h <= 200) {  // every rectangle with corners in [-1, w+1] x [-1, h+1]
    for (int y0 = -1; y0 <= h + 1; ++y0)
      for (int y1 = y0; y1 <= h + 1; ++y1)
        for (int x0 = -1; x0 <= w + 1; ++x0)
          for (int x1 = x0; x1 <= w + 1; ++x1) add(x0, y0, x1 - x0, y1 - y0);
  } else {
    add(0, 0, 1, 1), add(w - 1, 0, 1, 1), add(0, h - 1, 1, 1), add(w - 1, h - 1, 1, 1), add(w / 2, h / 2, 1, 1);
    add(0, 0, w, h);                  // the whole map
    add(-3, -5, w + 9, h + 7);        // covering it
    const int sx = std::max(2, w / 3), sy = std::max(2, h / 3);
    add(-sx / 2, h / 3, sx, sy);      // straddling the left edge
    add(w - sx / 2, h / 3, sx, sy);   // the right edge
    add(w / 3, -sy / 2, sx, sy);      // the top edge
    add(w / 3, h - sy / 2, sx, sy);   // the bottom edge
    add(-sx / 2, -sy / 2, sx, sy), add(w - sx / 2, -sy / 2, sx, sy);  // the corners
    add(-sx / 2, h - sy / 2, sx, sy), add(w - sx / 2, h - sy / 2, sx, sy);
    add(-10, 0, 10, h), add(w, 0, 3, h), add(0, -7, w, 7), add(0, h, w, 2), add(w + 5, h + 5, 10, 10);  // outside
    add(5, 5, 0, 3), add(5, 5, 3, 0), add(5, 5, -4, 6), add(w + 3, 2, -8, 4);  // empty
    add(0, h / 2, w, 1), add(w / 2, 0, 1, h), add(0, h - 1, w, 1), add(w - 1, 0, 1, h);  // whole rows, columns
    std::mt19937 rng(static_cast<std::uint32_t>(w * 7919 + h));
    const auto below = [&rng](int n) { return static_cast<int>(rng() % static_cast<std::uint32_t>(n)); };
    const int random = w * h > 100000 ? 12 : 24;  // fewer on 1024², where each costs up to 10^6 texels on the CPU
    for (int i = 0; i < random; ++i) {  // inside
      const int rw = 1 + below(w), rh = 1 + below(h);
      add(below(w - rw + 1), below(h - rh + 1), rw, rh);
    }
    for (int i = 0; i < random; ++i)  // anywhere across the edges
      add(below(2 * w) - w / 2, below(2 * h) - h / 2, below(w + w / 2 + 1), below(h + h / 2 + 1));
  }
  add(-1000, -1000, 1 << 20, 1 << 20);  // huge, covering the map
  add(-(1 << 20), 0, 1 << 20, h);       // huge, wholly outside
  add(w, h, -w, -h);                    // negative size
  return out;
}

}  // namespace

float summed_area_digit(std::uint64_t v, int which) {
  return static_cast<float>((v >> (24 * which)) & (which < 2 ? 0xffffffu : 0xffffu));
}

CaseResult summed_area_bounded_case(const std::string& name, const std::vector<double>& expected,
                                    const std::vector<float>& observed, const std::vector<double>& bounds, int channels,
                                    const std::vector<int>& queries) {
  BoundedElements elements;
  for (size_t i = 0; i < expected.size(); ++i) {
    const int k = queries[i / static_cast<size_t>(channels)];
    elements.add(expected[i], observed[i], bounds[i], k % kSummedAreaGridWidth, k / kSummedAreaGridWidth,
                 static_cast<int>(i) % channels);
  }
  CaseResult r{name, {}, {}};
  r.comparison = compare_bounded(elements, r.tolerance);
  return r;
}

void name_summed_area_worst_rect(CaseResult& r, const std::vector<Rect>& rects) {
  if (r.comparison.pass || r.comparison.x < 0) return;
  const size_t k = static_cast<size_t>(r.comparison.y) * kSummedAreaGridWidth + static_cast<size_t>(r.comparison.x);
  if (k >= rects.size()) return;
  const Rect& q = rects[k];
  r.name += "; worst: rectangle from (" + std::to_string(q.x) + ", " + std::to_string(q.y) + "), " +
            std::to_string(q.width) + "x" + std::to_string(q.height);
}

std::vector<CaseResult> summed_area_depth_cases(const CheckEnvironment& env) {
  const SummedAreaPass pass(env.device, env.tree);
  const SummedAreaPass wrapping(env.device, env.tree, kWrapFractionBits);
  std::vector<CaseResult> results;
  for (const auto& fixture : check_texture_fixtures(env)) {
    for (const auto& size : kSizes) {
      const Image raw = generate_fixture(fixture, size.width, size.height);
      const std::vector<Rect> rects = rects_for(size.width, size.height);
      for (const Range& range : kRanges) {
        const Image map = in_range(raw, range);
        const SummedAreaPass& p = range.fraction_bits == kSummedAreaFractionBits ? pass : wrapping;
        const SummedAreaTable table = p.build(*env.device.upload(map), map.width, map.height);
        const std::vector<SummedAreaQueryResult> observed = p.query(table, rects);
        const SummedAreaReference reference(map, range.fraction_bits);

        const int n = static_cast<int>(rects.size());
        const int gw = std::min(n, kSummedAreaGridWidth), gh = (n + kSummedAreaGridWidth - 1) / kSummedAreaGridWidth;
        Image want(gw, gh, 5, 0.0f), got(gw, gh, 5, 0.0f);
        std::vector<double> e_float, bounds;
        std::vector<float> o_float;
        std::vector<int> in_float;  // the rectangle of each float-case query
        long left_out = 0;
        for (int k = 0; k < n; ++k) {
          const SummedAreaSums s = reference.sums(rects[static_cast<size_t>(k)]);
          const SummedAreaQueryResult& r = observed[static_cast<size_t>(k)];
          const int x = k % kSummedAreaGridWidth, y = k / kSummedAreaGridWidth;
          for (int d = 0; d < 3; ++d) want.at(x, y, d) = summed_area_digit(s.fixed_sum, d), got.at(x, y, d) = summed_area_digit(r.fixed_sum, d);
          want.at(x, y, 3) = static_cast<float>(s.count), got.at(x, y, 3) = static_cast<float>(r.count);
          want.at(x, y, 4) = static_cast<float>(s.texels), got.at(x, y, 4) = static_cast<float>(r.texels);
          if (!s.fixed_sum_fits()) {
            ++left_out;
            continue;
          }
          in_float.push_back(k);
          e_float.insert(e_float.end(), {s.sum, s.mean()});
          o_float.insert(o_float.end(), {r.sum, r.mean});
          bounds.insert(bounds.end(), {summed_area_sum_bound(s), summed_area_mean_bound(s)});
        }
        const std::string label = std::string(fixture.name) + " " + std::to_string(size.width) + "x" +
                                  std::to_string(size.height) + ", " + range.name + ", " + std::to_string(n) +
                                  " rectangles";
        results.push_back({label + ": fixed-point sum mod 2^64 ([0..2] 24/24/16-bit digits), [3] finite texels, "
                                   "[4] texels covered",
                           Tolerance::exact(), compare(want, got, Tolerance::exact())});
        name_summed_area_worst_rect(results.back(), rects);
        if (e_float.empty()) continue;
        std::string name = label + ": [0] depth sum, [1] mean vs double, each within its derived bound";
        if (left_out > 0) name += " (" + std::to_string(left_out) + " whose sum exceeds 63 bits left out)";
        results.push_back(summed_area_bounded_case(name, e_float, o_float, bounds, 2, in_float));
        name_summed_area_worst_rect(results.back(), rects);
      }
    }
  }
  return results;
}

std::vector<CaseResult> run_summed_area_check(const CheckEnvironment& env) {
  std::vector<CaseResult> results = summed_area_depth_cases(env);
  for (CaseResult& r : summed_area_moments_cases(env)) results.push_back(std::move(r));
  return results;
}

}  // namespace pn
