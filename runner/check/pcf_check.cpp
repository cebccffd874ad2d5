// Cases of the pcf check: glsl/pcf.glsl through passes/pcf_query.comp against
// pcf_reference (the definition in double), on every fixture at 300×300 (the
// raw maps: NaN and ±Inf texels included), for windows of side 1…640 inside
// the map, straddling each edge, wholly outside, covering it, non-square,
// empty; receivers at the window's min and max depth (bias 0: a texel equal to
// dP - bias must not occlude), below, above, between (bias 0.01), NaN and +Inf.
// Three ways per fixture: one pnPcfWindow call; bands of 1, 7 or 128 rows added
// up with pnPcfAddRows (the pipeline's banded scan); and the pass compiled with
// PN_PCF_MAX_SIDE 64, so that windows beyond the bound are cut to it. And per fixture,
// pnPcfBilinearVisibility (2×2 bilinear PCF, the hard shadow) against its definition, and
// pnPcf's receiver-plane overload against the plane's definition.
// Occluder and texel counts must be exact. The depth sum is a float sum of n
// non-negative terms (every fixture depth is >= 0) in some order: its relative
// error is at most (n - 1) u / (1 - (n - 1) u), u = 2^-24, plus u for rounding
// the reference to float — the bound is (n + 1) u (1 + n u), n the case's
// largest occluder count (small windows, side <= 16, are their own cases so
// that their bound stays tight). A query with bias != 0 whose threshold
// dP - bias lies within one float ulp of a covered texel is left out (the
// float subtraction may decide that texel either way); the number is printed,
// and a last case requires it to stay below 1 % of the queries.
#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <random>
#include <string>

#include "check/compare.h"
#include "check/module_check.h"
#include "check/occlusion_sums.h"
#include "check/pcss_compare.h"
#include "core/error.h"
#include "fixture_images/texture_fixture.h"
#include "gl/texture.h"
#include "pass_runners/pcf_pass.h"
#include "reference/pcf_reference.h"

namespace pn {
namespace {

constexpr int kMapSize = 300;
constexpr int kSmallMaxSide = 64;  // the bounded variant's PN_PCF_MAX_SIDE

struct Window {
  Rect w;
  const char* where;
};

std::vector<Window> windows() {
  const int n = kMapSize;
  std::vector<Window> out;
  for (int s : {1, 2, 3, 5, 8, 16, 17, 31, 64, 100, 255, 300, 301, 640}) {
    if (s <= n) out.push_back({{(s * 7) % (n - s + 1), (s * 13) % (n - s + 1), s, s}, "inside"});
    out.push_back({{-s / 2 - 1, (s * 5) % n, s, s}, "straddling left"});
    out.push_back({{(s * 3) % n, -s / 2 - 1, s, s}, "straddling top"});
    out.push_back({{n - s / 2 - 1, n - s / 2 - 1, s, s}, "straddling bottom right"});
    out.push_back({{n + 2, (s * 11) % n, s, s}, "outside right"});
    out.push_back({{(s * 11) % n, -s - 3, s, s}, "outside top"});
    if (s > n) out.push_back({{-(s - n) / 2, -(s - n) / 3, s, s}, "covering the map"});
    if (s <= n) out.push_back({{(s * 17) % (n - s + 1), 4, s, std::max(1, s / 3)}, "non-square"});
  }
  out.push_back({{10, 10, 0, 5}, "empty (width 0)"});
  out.push_back({{10, 10, 5, -3}, "empty (height < 0)"});
  out.push_back({{-1000, -1000, 1 << 20, 1 << 20}, "huge, covering the map"});
  out.push_back({{0, 0, n, n}, "the whole map"});
  out.push_back({{n - 1, n - 1, 1, 1}, "the last texel"});
  return out;
}

struct Receiver {
  float depth, bias;
};

// Relative to the covered texels' finite depths: at the min and max (bias 0),
// below and above, between with a bias, NaN, +Inf.
std::vector<Receiver> receivers_for(const Image& map, const PcfCover& c, size_t salt) {
  float lo = INFINITY, hi = -INFINITY;
  for (long y = c.y0; y < c.y1; ++y)
    for (long x = c.x0; x < c.x1; ++x) {
      const float d = map.at(static_cast<int>(x), static_cast<int>(y));
      if (std::isfinite(d)) lo = std::min(lo, d), hi = std::max(hi, d);
    }
  if (!(lo <= hi)) lo = 0.25f, hi = 0.75f;  // nothing finite covered
  std::vector<Receiver> r{{lo, 0.0f}, {hi, 0.0f}, {lo - 0.05f, 0.0f}, {hi + 0.05f, 0.0f},
                          {0.5f * (lo + hi) + 0.0137f, 0.01f}};  // threshold off the fixtures' levels
  r.push_back(salt % 2 == 0 ? Receiver{NAN, 0.0f} : Receiver{INFINITY, 0.0f});
  return r;
}

// Whether float rounding of dP - bias may decide a covered texel differently from the definition.
bool threshold_tie(const Image& map, const PcfCover& c, const Receiver& r) {
  if (r.bias == 0.0f || !std::isfinite(r.depth)) return false;  // dP - 0 is exact
  const double t = static_cast<double>(r.depth) - r.bias;
  const double margin = 2.0 * FLT_EPSILON * std::max(std::fabs(t), static_cast<double>(FLT_MIN));
  for (long y = c.y0; y < c.y1; ++y)
    for (long x = c.x0; x < c.x1; ++x)
      if (std::fabs(map.at(static_cast<int>(x), static_cast<int>(y)) - t) <= margin) return true;
  return false;
}

OcclusionSums sums(const PcfSums& s) {
  return {static_cast<double>(s.occluders), s.depth_sum, static_cast<double>(s.texels)};
}

OcclusionSums sums(const PcfQueryResult& s) { return {s.occluders, s.depth_sum, s.texels}; }

// The bilinear queries run on the GPU against their expected visibilities: only the bilinear
// weights round (a few float operations on values <= 1), absolute 1e-6.
CaseResult bilinear_result(const PcfQueryPass& pass, const DeviceTexture& texture, const std::vector<PcfBilinearQuery>& queries,
                           const std::vector<float>& expected, const std::string& name) {
  const std::vector<float> observed = pass.bilinear(texture, queries);
  Image want(static_cast<int>(expected.size()), 1, 1), got(static_cast<int>(expected.size()), 1, 1);
  for (size_t k = 0; k < expected.size(); ++k) want.texels[k] = expected[k], got.texels[k] = observed[k];
  const Tolerance tolerance = Tolerance::absolute(1e-6);
  return {name, tolerance, compare(want, got, tolerance)};
}

// 2×2 bilinear PCF at positions inside, on texel centres, across the edges and outside the map,
// and NaN / Inf; receivers at the nearest texel's depth (bias 0: a texel equal to the threshold
// does not occlude), just before and behind it, with a bias, NaN and +Inf. The threshold is
// the same float subtraction on both sides (correctly rounded in GLSL), so only the bilinear
// weights round: a few float operations on values <= 1, absolute 1e-6.
CaseResult bilinear_case(const PcfQueryPass& pass, const DeviceTexture& texture, const Image& map, const std::string& label) {
  std::mt19937 random(0xb111);
  std::uniform_real_distribution<float> position(-3.0f, kMapSize + 3.0f);
  std::vector<std::pair<float, float>> positions{{0.5f, 0.5f}, {kMapSize - 0.5f, kMapSize - 0.5f}, {0.0f, 150.25f},
                                                 {kMapSize + 0.0f, 3.75f}, {-40.0f, -40.0f}, {1e30f, 5.0f},
                                                 {NAN, 3.0f}, {3.0f, INFINITY}};
  for (int k = 0; k < 600; ++k) positions.push_back({position(random), position(random)});
  for (int k = 0; k < 100; ++k) positions.push_back({std::floor(position(random)) + 0.5f, std::floor(position(random)) + 0.5f});
  std::vector<PcfBilinearQuery> queries;
  std::vector<float> expected;
  for (const auto& [x, y] : positions) {
    const int tx = std::clamp(std::isfinite(x) ? static_cast<int>(std::floor(x)) : 0, 0, kMapSize - 1);
    const int ty = std::clamp(std::isfinite(y) ? static_cast<int>(std::floor(y)) : 0, 0, kMapSize - 1);
    const float d = std::isfinite(map.at(tx, ty)) ? map.at(tx, ty) : 0.5f;
    for (const auto& [receiver, bias] : {std::pair{d, 0.0f}, {d + 0.02f, 0.0f}, {d - 0.02f, 0.0f}, {d + 0.05f, 0.01f},
                                         {NAN, 0.0f}, {INFINITY, 0.0f}}) {
      queries.push_back({x, y, receiver, bias});
      expected.push_back(static_cast<float>(pcf_bilinear_reference(map, x, y, receiver - bias)));
    }
  }
  return bilinear_result(pass, texture, queries, expected, label + " 2x2 bilinear PCF (hard shadow) vs the definition in double");
}

// The same with a receiver plane (pnPcf's plane overload): each of the four texels against the
// plane at its own centre, shallow to steep gradients, positions inside, across the edges and
// outside the map. A query with a texel within rounding of its own threshold (2^-20 of the
// magnitudes: the GPU rounds the threshold's terms in float) is left out and counted; the rest
// within the bilinear weights' rounding, 1e-6.
CaseResult bilinear_plane_case(const PcfQueryPass& pass, const DeviceTexture& texture, const Image& map,
                               const std::string& label) {
  std::mt19937 random(0xb112);
  std::uniform_real_distribution<float> position(-3.0f, kMapSize + 3.0f), slope(-0.3f, 0.3f);
  std::vector<PcfBilinearQuery> queries;
  std::vector<float> expected;
  int open = 0;
  for (int k = 0; k < 700; ++k) {
    const float x = position(random), y = position(random);
    const int tx = std::clamp(static_cast<int>(std::floor(x)), 0, kMapSize - 1);
    const int ty = std::clamp(static_cast<int>(std::floor(y)), 0, kMapSize - 1);
    const float d = std::isfinite(map.at(tx, ty)) ? map.at(tx, ty) : 0.5f;
    const float scale = k % 3 == 0 ? 0.01f : k % 3 == 1 ? 0.1f : 1.0f;  // shallow to steep
    const PcfBilinearQuery q{x, y, d + 0.001f * static_cast<float>(k % 7 - 3), 0.002f, scale * slope(random),
                             scale * slope(random)};
    const BilinearPlane r = pcf_bilinear_reference_plane(map, q.x, q.y, q.receiver_depth, q.gradient_u, q.gradient_v,
                                                         q.bias, std::ldexp(1.0, -20));
    if (r.open || (q.gradient_u == 0.0f && q.gradient_v == 0.0f)) {
      ++open;
      continue;
    }
    queries.push_back(q);
    expected.push_back(static_cast<float>(r.visibility));
  }
  return bilinear_result(pass, texture, queries, expected,
                         label + " 2x2 bilinear PCF with a receiver plane vs the definition in double (" +
                             std::to_string(open) + " of 700 queries within rounding of a texel's threshold left out)");
}

// A query's receiver plane in the plane cases: gradients of either sign, unequal in u and v, from
// shallow to steep (light depth a texel), so that u and v cannot trade places unseen.
PcfPlane plane_for(size_t k) {
  const float scale = k % 3 == 0 ? 0.001f : k % 3 == 1 ? 0.01f : 0.05f;
  const float su = k % 2 == 0 ? 1.0f : -1.0f, sv = (k / 2) % 2 == 0 ? 1.0f : -1.0f;
  return {su * scale, -0.37f * sv * scale, 0.0f, 0.0f};
}

// The windows with a receiver plane (pnPcfWindowPlane, and pnPcfAddRowsPlane in bands of 1, 7 and
// 128 rows) against pcf_reference_plane: every third window, its receivers as the plain windows' (NaN and
// +Inf among them) at a point inside it off its centre ((0.3, 0.7) of its sides), each texel against
// the plane at its own centre, never above dP - bias. A query with a texel within rounding of its
// threshold (2^-20 of the magnitudes) is left out and counted.
void window_plane_cases(const PcfQueryPass& pass, const DeviceTexture& texture, const Image& map,
                        const std::vector<Window>& windows, const std::string& label, std::vector<CaseResult>& results) {
  std::vector<PcfQuery> queries;
  std::vector<PcfPlane> planes;
  std::vector<PcfSums> expected;
  std::vector<bool> open;
  for (size_t i = 0; i < windows.size(); i += 3) {  // every third window: the plane's arithmetic, not the clip again
    const Rect& w = windows[i].w;
    const PcfCover c = pcf_cover(w, map.width, map.height, kPcfMaxSide);
    for (const Receiver& r : receivers_for(map, c, i)) {
      static constexpr int kBands[4] = {0, 1, 7, 128};
      PcfPlane plane = plane_for(queries.size());
      plane.centre_u = static_cast<float>(w.x) + 0.3f * static_cast<float>(w.width);
      plane.centre_v = static_cast<float>(w.y) + 0.7f * static_cast<float>(w.height);
      queries.push_back({w.x, w.y, w.width, w.height, r.depth, r.bias, kBands[queries.size() % 4]});
      planes.push_back(plane);
      bool tie = false;
      expected.push_back(pcf_reference_plane(map, w, r.depth - r.bias,
                                             {plane.gradient_u, plane.gradient_v, plane.centre_u, plane.centre_v,
                                              std::ldexp(1.0, -20)},
                                             tie));
      open.push_back(tie);
    }
  }
  const std::vector<PcfQueryResult> observed = pass.run(texture, queries, planes);
  OcclusionBatch g;
  for (size_t k = 0; k < queries.size(); ++k) {
    if (open[k]) {
      ++g.left_out;
      continue;
    }
    g.expected.push_back(sums(expected[k]));
    g.observed.push_back(sums(observed[k]));
  }
  add_occlusion_cases(results, label + " windows with a receiver plane (whole and in bands of 1, 7, 128 rows)", g,
                      "texels", "a texel within rounding of its plane threshold");
}

// The area-weighted window (issue 51: pnRegionArea + pnPcfAreaPlane, whole and in bands of 1, 7
// and 128 rows) against pcf_area_reference: continuous centres inside, across the edges and
// outside the map, sides from below one texel to past the map's, NaN and infinite inputs;
// receivers at the nearest texel's depth, before and behind it (twice), with a bias, NaN and +Inf. The
// decisions are exact (the same float threshold); what rounds: the square's edges, formed in float
// (each edge texel's weight within 4u (|c| + s) of its value, at most 4 (s + 2) edge texels), and
// the float sums of non-negative terms ((k + 2) u of the total, k the texels touched), per value:
// [0] occluded area, [1] its depth-weighted sum, [2] the area read, [3] pnPcfBlockerMean (odd
// queries) or pnPcfOccludedFraction (even) of the sums — fractional counts, areas below ½ among
// them (squares almost wholly off the map), within the quotient of both terms' bounds.
// With `plane`: each query with plane_for's gradient about the square's centre (pnPcfAreaPlane,
// pnPcfAddAreaRowsPlane) against pcf_area_reference_plane; the squares of non-finite inputs or
// sides over 34, and the queries with a texel within rounding of its threshold left out.
CaseResult area_case(const PcfQueryPass& pass, const DeviceTexture& texture, const Image& map, const std::string& label,
                     bool plane = false) {
  constexpr double u = 0x1p-24;
  float deepest = 0.0f;
  for (float d : map.texels)
    if (std::isfinite(d)) deepest = std::max(deepest, std::fabs(d));
  std::mt19937 random(0xa4ea);
  std::uniform_real_distribution<float> position(-20.0f, kMapSize + 20.0f), fraction(0.0f, 1.0f);
  std::vector<std::array<float, 3>> squares{{150.0f, 150.0f, 7.0f},        {150.5f, 150.5f, 7.0f},
                                            {0.25f, 0.75f, 3.5f},          {kMapSize - 0.3f, 4.2f, 9.9f},
                                            {-2.0f, 40.0f, 3.0f},          {-1.25f, 40.0f, 3.0f},
                                            {150.0f, 150.0f, 0.25f},       {150.3f, 150.6f, 1.0f},
                                            {150.0f, 150.0f, kMapSize * 1.5f}, {150.0f, 150.0f, 1e30f},
                                            {NAN, 33.3f, 5.5f},            {12.5f, INFINITY, 5.5f},
                                            {77.7f, 88.8f, NAN},           {77.7f, 88.8f, -4.0f},
                                            {-0.3f, 40.5f, 1.0f},          {kMapSize + 0.2f, 77.5f, 1.0f},
                                            {-0.35f, 200.5f, 1.0f},        {120.5f, -0.1f, 1.5f}};  // areas < 1/2
  for (float side : {1.0f, 1.5f, 2.7f, 5.25f, 16.4f, 33.9f, 100.6f, 299.5f})
    for (int k = 0; k < 12; ++k) squares.push_back({position(random), position(random), side + 0.1f * fraction(random)});
  std::vector<PcfAreaQuery> queries;
  std::vector<PcfPlane> planes;
  std::vector<PcfAreaSums> expected;
  std::vector<double> position_error;
  int left_out = 0;
  for (const auto& [x, y, side] : squares) {
    // With the plane: the finite squares up to 34 texels a side (its arithmetic; the edges are the
    // plain case's).
    if (plane && !(std::isfinite(x) && std::isfinite(y) && std::isfinite(side) && side <= 34.0f)) continue;
    const int tx = std::clamp(std::isfinite(x) ? static_cast<int>(std::floor(x)) : 0, 0, kMapSize - 1);
    const int ty = std::clamp(std::isfinite(y) ? static_cast<int>(std::floor(y)) : 0, 0, kMapSize - 1);
    const float d = std::isfinite(map.at(tx, ty)) ? map.at(tx, ty) : 0.5f;
    // Seven receivers a square: each one meets both ratios (odd and even queries) over the squares.
    for (const auto& [receiver, bias] : {std::pair{d, 0.0f}, {d + 0.02f, 0.0f}, {d - 0.02f, 0.0f}, {d + 0.05f, 0.01f},
                                         {d + 0.03f, 0.0f}, {NAN, 0.0f}, {INFINITY, 0.0f}}) {
      static constexpr int kBands[4] = {0, 1, 7, 128};
      const PcfPlane p = plane_for(queries.size() + static_cast<size_t>(left_out));
      bool open = false;
      const PcfAreaSums sums = plane ? pcf_area_reference_plane(map, x, y, side, receiver - bias,
                                                                {p.gradient_u, p.gradient_v, x, y, std::ldexp(1.0, -20)}, open)
                                     : pcf_area_reference(map, x, y, side, receiver - bias);
      if (open) {
        ++left_out;
        continue;
      }
      queries.push_back({x, y, side, receiver, bias, kBands[queries.size() % 4]});
      planes.push_back(p);
      expected.push_back(sums);
      position_error.push_back(area_corner_error(x, y, side, kMapSize));
    }
  }
  const std::vector<PcfQueryResult> observed = plane ? pass.area(texture, queries, planes) : pass.area(texture, queries);
  BoundedElements e;
  for (size_t k = 0; k < queries.size(); ++k) {
    const PcfAreaSums& x = expected[k];
    const double rounding = (x.touched + 2) * u;
    const int at = static_cast<int>(k);
    e.add(x.occluders, observed[k].occluders, rounding * x.occluders + position_error[k], at, 0, 0);
    e.add(x.depth_sum, observed[k].depth_sum, rounding * x.depth_sum + position_error[k] * deepest, at, 0, 1);
    e.add(x.area, observed[k].texels, rounding * x.area + position_error[k], at, 0, 2);
    // [3] the sums' ratio through the module's own helpers (odd queries the blocker mean, even the
    // occluded fraction), within both terms' bounds; a blocker mean whose occluded area is within
    // rounding of none is left out (a texel the edge's rounding touches may decide it).
    const double occluded_bound = rounding * x.occluders + position_error[k];
    if (k % 2 == 1 && x.occluders > occluded_bound) {
      const double mean = x.depth_sum / x.occluders;
      const double sum_bound = rounding * x.depth_sum + position_error[k] * deepest;
      e.add(mean, observed[k].ratio,
            (sum_bound + mean * occluded_bound) / (x.occluders - occluded_bound) + 2.0 * u * mean, at, 0, 3);
    } else if (k % 2 == 0) {
      const double area_bound = rounding * x.area + position_error[k];
      const double fraction = x.area > 0.0 ? x.occluders / x.area : 0.0;
      const double bound = x.area > area_bound ? fraction * (occluded_bound / std::max(x.occluders, occluded_bound) +
                                                             area_bound / (x.area - area_bound) + 2.0 * u) +
                                                     occluded_bound / (x.area - area_bound)
                                               : 1.0;
      e.add(fraction, observed[k].ratio, bound, at, 0, 3);
    }
  }
  Tolerance tolerance;
  const Comparison c = compare_bounded(e, tolerance);
  return {label + " area-weighted window (pnRegionArea, pnPcfAreaPlane whole and in bands of 1, 7, 128 rows" +
              (plane ? ", with a receiver plane about its centre; " + std::to_string(left_out) +
                           " queries within rounding of a plane threshold left out"
                     : std::string()) +
              ") vs every texel's overlap in double (" + std::to_string(queries.size()) + " queries): [0] occluded area, "
                  "[1] depth-weighted, [2] area, [3] blocker mean (odd) or occluded fraction (even)",
          tolerance, c};
}

}  // namespace

std::vector<CaseResult> run_pcf_check(const CheckEnvironment& env) {
  const PcfQueryPass pass(env.device, env.tree);
  const PcfQueryPass bounded(env.device, env.tree, kSmallMaxSide);
  const std::vector<Window> all_windows = windows();
  std::vector<CaseResult> results;
  long queries_total = 0, left_out_total = 0;

  for (const auto& fixture : check_texture_fixtures(env)) {
    const Image map = generate_fixture(fixture, kMapSize, kMapSize);
    for (float d : map.texels)
      if (std::isfinite(d) && d < 0.0f) throw Error(std::string("pcf check: fixture '") + fixture.name + "' has depths < 0");
    const std::unique_ptr<DeviceTexture> uploaded = env.device.upload(map);
    const DeviceTexture& texture = *uploaded;
    const std::string label = std::string(fixture.name) + " " + std::to_string(kMapSize) + "x" + std::to_string(kMapSize);

    struct Variant {
      const char* name;
      const PcfQueryPass* pass;
      int max_side;
      bool bands;
    };
    const Variant variants[] = {{"whole window", &pass, kPcfMaxSide, false},
                                {"bands of 1, 7, 128 rows", &pass, kPcfMaxSide, true},
                                {"PN_PCF_MAX_SIDE 64", &bounded, kSmallMaxSide, false}};
    for (const Variant& v : variants) {
      std::vector<PcfQuery> queries;
      std::vector<PcfSums> expected;
      std::vector<bool> small, tie;
      for (size_t i = 0; i < all_windows.size(); ++i) {
        const Rect& w = all_windows[i].w;
        const PcfCover c = pcf_cover(w, map.width, map.height, v.max_side);
        for (const Receiver& r : receivers_for(map, c, i)) {
          static constexpr int kBands[3] = {1, 7, 128};
          const int band = v.bands ? kBands[queries.size() % 3] : 0;
          queries.push_back({w.x, w.y, w.width, w.height, r.depth, r.bias, band});
          expected.push_back(pcf_reference(map, w, r.depth, r.bias, v.max_side));
          small.push_back(std::max(c.x1 - c.x0, c.y1 - c.y0) <= 16);
          tie.push_back(threshold_tie(map, c, r));
        }
      }
      const std::vector<PcfQueryResult> observed = v.pass->run(texture, queries);
      OcclusionBatch groups[2];
      for (size_t k = 0; k < queries.size(); ++k) {
        OcclusionBatch& g = groups[small[k] ? 0 : 1];
        if (tie[k]) {
          ++g.left_out;
          continue;
        }
        g.expected.push_back(sums(expected[k]));
        g.observed.push_back(sums(observed[k]));
      }
      queries_total += static_cast<long>(queries.size());
      left_out_total += groups[0].left_out + groups[1].left_out;
      add_occlusion_cases(results, label + " " + v.name + ", sides <= 16", groups[0], "texels", "dP - bias ties a texel");
      add_occlusion_cases(results, label + " " + v.name + ", sides > 16", groups[1], "texels", "dP - bias ties a texel");
    }
    results.push_back(bilinear_case(pass, texture, map, label));
    results.push_back(bilinear_plane_case(pass, texture, map, label));
    results.push_back(area_case(pass, texture, map, label));
    results.push_back(area_case(pass, texture, map, label, true));
    window_plane_cases(pass, texture, map, all_windows, label, results);
  }
  const bool few = left_out_total * 100 <= queries_total;
  const Image want(1, 1, 1, 1.0f), got(1, 1, 1, few ? 1.0f : 0.0f);
  results.push_back({"queries left out for rounding ties: " + std::to_string(left_out_total) + " of " +
                         std::to_string(queries_total) + " (<= 1 %)",
                     Tolerance::exact(), compare(want, got, Tolerance::exact())});
  return results;
}

}  // namespace pn
