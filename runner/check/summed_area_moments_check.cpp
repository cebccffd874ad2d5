// The summed_area check's moments-table cases: glsl/summed_area.glsl's fixed-
// point (Σq, Σq² modulo 2^64) and float (Σ(x − ½), Σ(x − ½)²) tables, built
// by passes/summed_area_build.comp and read by
// passes/summed_area_moments_query.comp, against SummedAreaMomentsReference
// (every rectangle summed texel by texel; never a table on the CPU).
//
// Depths: light depth d = 20 + 20 v (v the fixture's value), +Inf where
// v >= 0.95 ("empty" texels at x = 1), NaN and ±Inf of the nonfinite fixture
// kept; the table's range is [1, 100], so x lies in [0.19, 0.40] plus the
// texels at 1 — the setting where E[x²] − E[x]² cancels.
// Maps: every fixture at 1×1, 3×5 and 17×9 with every rectangle whose corners
// lie in [−1, N+1] × [−1, M+1] (inside, straddling, outside, empty), the
// noise at 17×9 with B = 12 as well; noise and boxes at 512², 1024², 2048²
// with rectangles of every size class (sides 1, 2–3, 4–7, …, up to N: squares
// inside and straddling an edge or a corner, thin rows and columns inside and
// straddling) and the whole map, covering, outside and empty ones.
// Cases per map:
//   exact — Σq and Σq² (modulo 2^64, as 24/24/16-bit digits) and the texels
//     covered equal the reference bit for bit;
//   fixed vs q · 2^-B — the GPU's mean and variance against the exact moments
//     of the quantised values, within the bound of pnSummedAreaRectMoments's
//     float arithmetic alone (8u · var + 20u ρ² 2^-2B on the variance);
//   fixed vs x — against the true x in double: plus e per texel on the mean,
//     2σe + e² on the variance (e = 2^-(B+1) + ε_x);
//   float vs x — the float table against the true x, within its data-
//     dependent bound (each prefix's γ_{X+Y−2} A(X, Y), the four corners').
// (Bounds: runner/reference/summed_area_reference.h; their derivation:
// docs/modules/summed_area.md.) Then one case per large size prints the
// worst errors of both tables against the true x beside each other (the fixed
// point's must be below the float's), and one that wrong inputs are refused.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "check/summed_area_check.h"
#include "core/error.h"
#include "core/format.h"
#include "fixture_images/texture_fixture.h"
#include "gl/texture.h"
#include "pass_runners/summed_area_pass.h"

namespace pn {
namespace {

constexpr double kNear = 1.0, kFar = 100.0;
constexpr int kLargeSizes[] = {512, 1024, 2048};
constexpr const char* kLargeFixtures[] = {"noise", "boxes"};
constexpr int kSmallBits = 12;  // one small map's tables compiled with B = 12: the define reaches the passes

Image light_depths(const Image& fixture) {
  Image out = fixture;
  for (float& d : out.texels)
    if (std::isfinite(d)) d = d >= 0.95f ? std::numeric_limits<float>::infinity() : 20.0f + 20.0f * d;
  return out;
}

// Every rectangle with corners in [−1, w+1] × [−1, h+1].
std::vector<Rect> every_rect(int w, int h) {
  std::vector<Rect> out;
  for (int y0 = -1; y0 <= h + 1; ++y0)
    for (int y1 = y0; y1 <= h + 1; ++y1)
      for (int x0 = -1; x0 <= w + 1; ++x0)
        for (int x1 = x0; x1 <= w + 1; ++x1) out.push_back({x0, y0, x1 - x0, y1 - y0});
  return out;
}

// Sides in every class [2^k, 2^(k+1) − 1] up to n (the last class ends at n).
std::vector<Rect> size_class_rects(int n) {
  std::vector<Rect> out;
  std::mt19937 rng(static_cast<std::uint32_t>(n) * 104729u + 17u);
  const auto between = [&rng](int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<std::uint32_t>(hi - lo + 1)); };
  // An origin whose rectangle of side s crosses the low or the high edge (for s = 1: just outside).
  const auto straddling = [&](int s) {
    if (s < 2) return rng() % 2 ? -1 : n;
    return rng() % 2 ? between(-s + 1, -1) : between(n - s + 1, n - 1);
  };
  for (int lo = 1; lo <= n; lo *= 2) {
    const int hi = std::min(2 * lo - 1, n);
    for (int i = 0; i < 2; ++i) {  // squares inside
      const int s = between(lo, hi);
      out.push_back({between(0, n - s), between(0, n - s), s, s});
    }
    const int s = between(lo, hi);  // a square across an edge (x, y or both: a corner)
    switch (rng() % 3) {
      case 0: out.push_back({straddling(s), between(0, n - s), s, s}); break;
      case 1: out.push_back({between(0, n - s), straddling(s), s, s}); break;
      default: out.push_back({straddling(s), straddling(s), s, s}); break;
    }
    const int t = between(lo, hi), thin = between(1, 3);
    out.push_back({between(0, n - t), between(0, n - thin), t, thin});  // a thin row inside
    out.push_back({between(0, n - thin), straddling(t), thin, t});      // a thin column across the top or bottom
    out.push_back({straddling(t), between(0, n - 1), t, 1});            // a row across the left or right edge
  }
  out.push_back({0, 0, n, n}), out.push_back({-3, -5, n + 9, n + 7});       // the whole map, covering it
  out.push_back({n - 1, n - 1, 1, 1}), out.push_back({0, n - 1, n, 1});    // where the float prefixes are largest
  out.push_back({n + 1, 0, 4, 4}), out.push_back({5, 5, 0, 3}), out.push_back({n, n, -n, -n});  // outside, empty
  return out;
}

struct MomentsMap {
  std::string name;
  Image depth;
  int bits = kSummedAreaMomentBits;
  std::vector<Rect> rects;
};

// Worst absolute errors of a map's queries against the true x.
struct WorstErrors {
  double fixed_mean = 0, fixed_variance = 0, float_mean = 0, float_variance = 0;
  void add(const WorstErrors& o) {
    fixed_mean = std::max(fixed_mean, o.fixed_mean), fixed_variance = std::max(fixed_variance, o.fixed_variance);
    float_mean = std::max(float_mean, o.float_mean), float_variance = std::max(float_variance, o.float_variance);
  }
};

double error_of(float observed, double expected) {
  return std::isfinite(observed) ? std::fabs(static_cast<double>(observed) - expected) : std::numeric_limits<double>::infinity();
}

// The map's four cases; returns its worst errors against the true x.
WorstErrors map_cases(const CheckEnvironment& env, const SummedAreaMomentsPass& pass, const MomentsMap& map,
                      std::vector<CaseResult>& results) {
  const UnitRange unit = unit_range(kNear, kFar);
  const MomentsDepthRange range{kNear, kFar, unit.offset, unit.scale};
  const std::unique_ptr<DeviceTexture> texture = env.device.upload(map.depth);
  const int w = map.depth.width, h = map.depth.height;
  const std::vector<MomentsQueryResult> fixed =
      pass.query(pass.build(*texture, w, h, MomentsTableKind::fixed, unit), map.rects);
  const MomentsTable float_table = pass.build(*texture, w, h, MomentsTableKind::floating, unit);
  const std::vector<MomentsQueryResult> floating = pass.query(float_table, map.rects);
  {  // The float table's row 0 and column 0 are the empty prefix, 0: a rectangle's four-corner
     // difference cancels a constant there, so the queries alone could not tell.
    const Image table = env.device.read_texture(*float_table.texture);
    Image border(table.width + table.height, 1, table.channels, 0.0f);
    for (int x = 0; x < table.width; ++x)
      for (int c = 0; c < table.channels; ++c) border.at(x, 0, c) = table.at(x, 0, c);
    for (int y = 0; y < table.height; ++y)
      for (int c = 0; c < table.channels; ++c) border.at(table.width + y, 0, c) = table.at(0, y, c);
    results.push_back({map.name + ": float table's row 0 and column 0 (texel k of the row, then of the column) are 0",
                       Tolerance::exact(),
                       compare(Image(border.width, 1, border.channels, 0.0f), border, Tolerance::exact())});
  }
  const SummedAreaMomentsReference reference(map.depth, range, map.bits);

  const int n = static_cast<int>(map.rects.size());
  const int gw = std::min(n, kSummedAreaGridWidth), gh = (n + kSummedAreaGridWidth - 1) / kSummedAreaGridWidth;
  Image want(gw, gh, 8, 0.0f), got(gw, gh, 8, 0.0f);
  std::vector<double> e_quantised, b_quantised, e_true, b_fixed, b_float;
  std::vector<float> o_fixed, o_float;
  std::vector<int> queries;
  WorstErrors worst;
  for (int k = 0; k < n; ++k) {
    const MomentsSums s = reference.sums(map.rects[static_cast<size_t>(k)]);
    const MomentsQueryResult& f = fixed[static_cast<size_t>(k)];
    const MomentsQueryResult& g = floating[static_cast<size_t>(k)];
    const int x = k % kSummedAreaGridWidth, y = k / kSummedAreaGridWidth;
    for (int d = 0; d < 3; ++d) {
      want.at(x, y, d) = summed_area_digit(s.sum_q, d), got.at(x, y, d) = summed_area_digit(f.sum_q, d);
      want.at(x, y, 3 + d) = summed_area_digit(s.sum_q2, d), got.at(x, y, 3 + d) = summed_area_digit(f.sum_q2, d);
    }
    want.at(x, y, 6) = want.at(x, y, 7) = static_cast<float>(s.texels);
    got.at(x, y, 6) = static_cast<float>(f.texels), got.at(x, y, 7) = static_cast<float>(g.texels);
    queries.push_back(k);
    const MomentsBounds arithmetic = reference.fixed_arithmetic_bound(s), bound = reference.fixed_bound(s),
                        float_bound = reference.float_bound(s);
    e_quantised.insert(e_quantised.end(), {s.quantised_mean, s.quantised_variance});
    b_quantised.insert(b_quantised.end(), {arithmetic.mean, arithmetic.variance});
    e_true.insert(e_true.end(), {s.mean, s.variance});
    o_fixed.insert(o_fixed.end(), {f.mean, f.variance});
    o_float.insert(o_float.end(), {g.mean, g.variance});
    b_fixed.insert(b_fixed.end(), {bound.mean, bound.variance});
    b_float.insert(b_float.end(), {float_bound.mean, float_bound.variance});
    worst.add({error_of(f.mean, s.mean), error_of(f.variance, s.variance), error_of(g.mean, s.mean),
               error_of(g.variance, s.variance)});
  }
  const std::string label = map.name + ", " + std::to_string(n) + " rectangles";
  const auto push = [&](CaseResult r) {
    results.push_back(std::move(r));
    name_summed_area_worst_rect(results.back(), map.rects);
  };
  push({label + ": moments tables, [0..2] sum of q and [3..5] of q^2 mod 2^64 (24/24/16-bit digits), texels "
                "covered [6] fixed, [7] float",
        Tolerance::exact(), compare(want, got, Tolerance::exact())});
  push(summed_area_bounded_case(label + ": fixed table vs the exact moments of q 2^-B: [0] mean, [1] variance within "
                                        "pnSummedAreaRectMoments's float arithmetic (8u var + 20u rho^2 2^-2B)",
                                e_quantised, o_fixed, b_quantised, 2, queries));
  push(summed_area_bounded_case(label + ": fixed table vs the true x: [0] mean within e = " +
                                    format_number("%.3g", reference.texel_bound()) +
                                    " a texel, [1] variance within 2 sigma e + e^2, plus the arithmetic",
                                e_true, o_fixed, b_fixed, 2, queries));
  push(summed_area_bounded_case(label + ": float table vs the true x: [0] mean, [1] variance within the prefix sums' "
                                        "rounding (gamma_{X+Y-2} A at each corner)",
                                e_true, o_float, b_float, 2, queries));
  return worst;
}

// Each of `attempts` must throw pn::Error: observed 1 where it did.
CaseResult refusals_case(const std::string& name, const std::vector<void (*)(const CheckEnvironment&)>& attempts,
                         const CheckEnvironment& env) {
  const int n = static_cast<int>(attempts.size());
  Image want(n, 1, 1, 1.0f), got(n, 1, 1, 0.0f);
  for (int i = 0; i < n; ++i) {
    try {
      attempts[static_cast<size_t>(i)](env);
    } catch (const Error&) {
      got.at(i, 0) = 1.0f;
    }
  }
  return {name, Tolerance::exact(), compare(want, got, Tolerance::exact())};
}

}  // namespace

std::vector<CaseResult> summed_area_moments_cases(const CheckEnvironment& env) {
  std::vector<CaseResult> results;
  const SummedAreaMomentsPass pass(env.device, env.tree);
  const SummedAreaMomentsPass coarse(env.device, env.tree, kSmallBits);
  const std::string depths = "light depth 20 + 20 v in [1, 100], +Inf where v >= 0.95";
  for (const auto& fixture : check_texture_fixtures(env))
    for (const auto& size : {fixtures::FixtureSize{1, 1}, {3, 5}, {17, 9}}) {
      const std::string name = std::string(fixture.name) + " " + std::to_string(size.width) + "x" +
                               std::to_string(size.height) + ", " + depths;
      const Image depth = light_depths(generate_fixture(fixture, size.width, size.height));
      map_cases(env, pass, {name, depth, kSummedAreaMomentBits, every_rect(size.width, size.height)}, results);
      if (std::string(fixture.name) == "noise" && size.width == 17)
        map_cases(env, coarse, {name + ", B " + std::to_string(kSmallBits), depth, kSmallBits,
                                every_rect(size.width, size.height)},
                  results);
    }
  for (int n : kLargeSizes) {
    if (env.options.quick && n != kLargeSizes[0]) break;  // the programs ran at 512²: 1024² and 2048² add data only
    WorstErrors worst;
    const std::vector<Rect> rects = size_class_rects(n);
    for (const char* fixture : kLargeFixtures) {
      const std::string name = std::string(fixture) + " " + std::to_string(n) + "x" + std::to_string(n) + ", " + depths;
      worst.add(map_cases(env, pass, {name, light_depths(generate_fixture(find_fixture(fixture), n, n)),
                                      kSummedAreaMomentBits, rects},
                          results));
    }
    // Observed: how far each fixed-point error exceeds the float one (0 when below).
    Image want(2, 1, 1, 0.0f), got(2, 1, 1, 0.0f);
    got.at(0, 0) = static_cast<float>(std::max(0.0, worst.fixed_mean - worst.float_mean));
    got.at(1, 0) = static_cast<float>(std::max(0.0, worst.fixed_variance - worst.float_variance));
    CaseResult summary{"moments " + std::to_string(n) + "x" + std::to_string(n) + " (noise, boxes; " +
                           std::to_string(rects.size()) + " rectangles each), worst error vs the true x: fixed point "
                           "mean " + format_number("%.2e", worst.fixed_mean) + ", variance " +
                           format_number("%.2e", worst.fixed_variance) + "; float mean " +
                           format_number("%.2e", worst.float_mean) + ", variance " +
                           format_number("%.2e", worst.float_variance) + ": [0] mean, [1] variance, fixed below float",
                       Tolerance::exact(), compare(want, got, Tolerance::exact())};
    summary.headline = true;
    results.push_back(summary);
  }
  results.push_back(refusals_case(
      "wrong input refused: unit_range of [-1, 10], [5, 5], [5, 4], [NaN, 1], [0, inf], [0, 1e300] (scale 0 in "
      "float), [0, 1e-300] (scale inf); moment bits -1 and 19 (pass and reference)",
      {[](const CheckEnvironment&) { unit_range(-1.0, 10.0); }, [](const CheckEnvironment&) { unit_range(5.0, 5.0); },
       [](const CheckEnvironment&) { unit_range(5.0, 4.0); },
       [](const CheckEnvironment&) { unit_range(std::numeric_limits<double>::quiet_NaN(), 1.0); },
       [](const CheckEnvironment&) { unit_range(0.0, std::numeric_limits<double>::infinity()); },
       [](const CheckEnvironment&) { unit_range(0.0, 1e300); }, [](const CheckEnvironment&) { unit_range(0.0, 1e-300); },
       [](const CheckEnvironment& e) { SummedAreaMomentsPass(e.device, e.tree, -1); },
       [](const CheckEnvironment& e) { SummedAreaMomentsPass(e.device, e.tree, kSummedAreaMaxMomentBits + 1); },
       [](const CheckEnvironment&) { SummedAreaMomentsReference(Image(1, 1, 1), {0, 1, 0, 1}, -1); },
       [](const CheckEnvironment&) { SummedAreaMomentsReference(Image(1, 1, 1), {0, 1, 0, 1}, 19); }},
      env));
  return results;
}

}  // namespace pn
