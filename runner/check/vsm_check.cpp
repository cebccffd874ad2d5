// Cases of the vsm check: glsl/vsm.glsl through passes/vsm_moments.comp, the
// blur pass over the moments and passes/vsm_query.comp, for VSM, EVSM-2 and
// EVSM-4, on every texture fixture at 37² and 64² (the raw maps: NaN and ±Inf
// texels included) and on the two-occluder map, against vsm_reference.
// Per map and kind (u = 2^-24, the unit roundoff; c the largest exponent used;
// mv the min variance, relative; a the bleeding reduction):
//   moments        VSM: exact (d and d*d in float are the definition rounded
//                  once). EVSM: relative <= 2 r_w + u, r_w = 2 u (11 c + 6):
//                  x = (d - near)/(far - near) within 6u (a division of 2.5
//                  ulp), c x within 7 u c, GLSL's exp within (3 + 2|c x|) ulp,
//                  doubled; the square adds 2 r_w + u.
//   blurred        per channel, against the direct 2-D Gaussian sum of the
//                  reference moments in double: the blur's bound
//                  (check/blur_tolerance.h) + (EVSM) the moments' relative
//                  bound times the channel's largest magnitude.
//   Chebyshev      p on the GPU's blurred moments (read back) vs the bound in
//                  double on the same moments: the float variance m2 - m1^2 is
//                  within u m1^2 + 4 u s2, i.e. u / mv + 4 u relative to
//                  s2 >= mv m1^2; dp = p (1 - p)(ds2 / s2 - d(delta^2) / delta^2)
//                  <= (u / mv + 7 u) / 4, plus 6 u for the division; doubled.
//                  EVSM adds the receiver's warp: dp <= r_w t |dp/dt| <=
//                  r_w (0.65 / sqrt(mv) + 0.5), from max 2 delta s2 |mu| / (s2 + delta^2)^2
//                  = (3 sqrt 3 / 8) |mu| / s <= 0.65 / sqrt(mv); doubled.
//   reduced        linstep(a, 1, p): the Chebyshev bound / (1 - a) + 8 u.
//   depth-range    the bound's decision (lit / shadowed / neither): exact, for
//                  receivers at the window's min and max and one float ulp in
//                  front of and behind each (bias 0), against a brute-force scan.
//   visibility     the module's pnVsmVisibility / pnEvsmVisibility2/4: the
//                  decision where it decides (exact), else the reduced bound.
// VSM again at radius 0 (no blur, the bound over the texel alone) on the noise and step-edge maps.
// Light bleeding on kTwoOccluders (receivers on the plane behind both
// occluders, every texel): the exact Gaussian-weighted PCF visibility over the
// blur's window by brute force, and the mean light in excess of it, for the
// Chebyshev bound alone, reduced, and with the depth-range bound; the cases
// require the reduction to lower it and the depth-range bound not to raise it.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "check/blur_tolerance.h"
#include "check/module_check.h"
#include "check/vsm_tolerance.h"
#include "core/format.h"
#include "fixture_images/texture_fixture.h"
#include "pass_runners/depth_pyramid_pass.h"
#include "pass_runners/vsm_pass.h"
#include "reference/vsm_reference.h"

namespace pn {
namespace {

using namespace vsm_tolerance;
constexpr int kSizes[] = {37, 64};
constexpr int kReceiversPerTexel = 8;
constexpr VsmKind kKinds[] = {VsmKind::vsm, VsmKind::evsm2, VsmKind::evsm4};

VsmParams params_for(VsmKind kind) {
  VsmParams p;
  p.kind = kind;
  p.near_depth = -0.1f;  // the fixtures' depths lie in [0, 1]: x in (0.07, 0.85), not at the clamp
  p.far_depth = 1.2f;
  return p;
}

Tolerance moments_tolerance(const VsmParams& p) {
  if (p.kind == VsmKind::vsm) return Tolerance::exact();
  return Tolerance::relative(2.0 * warp_error(p) + kU);
}

struct Map {
  std::string name;
  Image depth;
};

std::vector<Map> maps(const CheckEnvironment& env) {
  std::vector<Map> out;
  for (const auto& fixture : check_texture_fixtures(env))
    for (int n : kSizes)
      out.push_back({std::string(fixture.name) + " " + std::to_string(n) + "x" + std::to_string(n),
                     generate_fixture(fixture, n, n)});
  const auto& two = fixtures::kTwoOccluders;
  out.push_back({std::string(two.name) + " " + std::to_string(two.size) + "x" + std::to_string(two.size),
                 generate_two_occluders(two)});
  return out;
}

// Receivers of texel (x, y), kReceiversPerTexel of them: at the window's min and
// max and one ulp in front and behind (bias 0), one near the texel's depth with
// a bias, one between min and max — or NaN on every fifth texel.
std::vector<VsmQuery> receivers(const Image& depth, int x, int y, int radius) {
  const DepthRange r = window_depth_range(depth, x, y, radius);
  const float inf = std::numeric_limits<float>::infinity();
  const float lo = std::isfinite(r.min) ? r.min : 0.5f, hi = std::isfinite(r.max) ? r.max : 0.75f;
  const float d = depth.at(x, y);
  const float own = std::isfinite(d) ? d : 0.3f;
  const float between = (x + y) % 5 == 0 ? std::numeric_limits<float>::quiet_NaN() : lo + 0.37f * (hi - lo);
  const float at[kReceiversPerTexel] = {lo, std::nextafter(lo, -inf), std::nextafter(lo, inf), hi,
                                        std::nextafter(hi, -inf), std::nextafter(hi, inf), own + 0.05f, between};
  std::vector<VsmQuery> out;
  for (int i = 0; i < kReceiversPerTexel; ++i) out.push_back({x, y, at[i], i == 6 ? 0.01f : 0.0f});
  return out;
}

// Result channel `c` of the queries as an image: query i of texel (x, y) at (8 x + i, y).
Image as_image(const std::vector<Query>& results, int n, int c) {
  Image out(n * kReceiversPerTexel, n);
  for (size_t k = 0; k < results.size(); ++k) {
    const int texel = static_cast<int>(k) / kReceiversPerTexel, i = static_cast<int>(k) % kReceiversPerTexel;
    out.at((texel % n) * kReceiversPerTexel + i, texel / n) = results[k][static_cast<size_t>(c)];
  }
  return out;
}

struct GpuRun {
  Image moments, blurred;   // read back, vsm_moment_channels channels
  std::vector<Query> results;
};

struct Gpu {
  const CheckEnvironment& env;
  VsmMomentsPass moments;
  VsmQueryPass query;
  DepthPyramidBuilder pyramid;

  Image read(const VsmMoments& m) const {
    return channels_of(env.device.read_texture(*m.texture), 0, m.channels);
  }

  GpuRun run(const Image& depth, const std::vector<VsmQuery>& queries, const VsmParams& params) const {
    const int n = depth.width;
    const std::unique_ptr<DeviceTexture> map = env.device.upload(depth);
    const VsmMoments raw = moments.moments(*map, n, n, params);
    const VsmMoments blurred = moments.blurred(raw, params);
    const DepthPyramid built = pyramid.build(*map, n, n, 30);
    return {read(raw), read(blurred), query.run(blurred, built, queries, params)};
  }
};

void map_cases(const Gpu& gpu, const Map& map, const VsmParams& params, std::vector<CaseResult>& results) {
  const Image& depth = map.depth;
  const int n = depth.width;
  std::vector<VsmQuery> queries;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      for (const VsmQuery& q : receivers(depth, x, y, params.blur.radius)) queries.push_back(q);
  const GpuRun run = gpu.run(depth, queries, params);
  const std::string label = map.name + " " + vsm_kind_name(params.kind);

  const Image moments = vsm_moments_reference(depth, params);
  const Tolerance warp = moments_tolerance(params);
  results.push_back({label + ": moments vs the definition in double", warp, compare(moments, run.moments, warp)});

  const Image window = blur_reference(moments, params.blur);
  for (int c = 0; c < moments.channels; ++c) {
    const Image expected = channels_of(window, c, 1);
    const double magnitude = largest_finite_magnitude(channels_of(moments, c, 1), 1.0f);
    const double extra = params.kind == VsmKind::vsm ? 0.0 : warp.bound * magnitude;
    const Tolerance t = Tolerance::absolute(blur_tolerance(params.blur, channels_of(moments, c, 1)).bound + extra);
    results.push_back({label + ": blurred moment " + std::to_string(c) + " vs the direct 2-D Gaussian sum", t,
                       compare(expected, channels_of(run.blurred, c, 1), t)});
  }

  std::vector<Query> expected(queries.size());
  for (size_t k = 0; k < queries.size(); ++k) {
    const VsmQuery& q = queries[k];
    const float t = q.receiver_depth - q.bias;  // the float t the module forms
    const double p = vsm_bound(moments_at(run.blurred, q.x, q.y), t, params);
    const double reduced = reduce_bleeding(p, params.bleeding_reduction);
    const double code = depth_range_bound(window_depth_range(depth, q.x, q.y, params.blur.radius), t);
    expected[k] = {static_cast<float>(vsm_visibility(code, reduced)), static_cast<float>(p),
                   static_cast<float>(reduced), static_cast<float>(code)};
  }
  const Tolerance cheb = Tolerance::absolute(chebyshev_tolerance(params));
  const Tolerance red = Tolerance::absolute(reduced_tolerance(params));
  results.push_back({label + ": Chebyshev bound on the blurred moments vs double", cheb,
                     compare(as_image(expected, n, 1), as_image(run.results, n, 1), cheb)});
  results.push_back({label + ": bleeding reduction linstep(" + format_number("%g", params.bleeding_reduction) +
                         ", 1, p) vs double",
                     red, compare(as_image(expected, n, 2), as_image(run.results, n, 2), red)});
  results.push_back({label + ": depth-range bound at the window's min/max and 1 ulp either side vs a scan",
                     Tolerance::exact(), compare(as_image(expected, n, 3), as_image(run.results, n, 3), Tolerance::exact())});
  results.push_back({label + ": visibility (bound, else reduced Chebyshev)", red,
                     compare(as_image(expected, n, 0), as_image(run.results, n, 0), red)});
}

struct Bleeding {
  double chebyshev = 0, reduced = 0, bounded = 0, bounded_reduced = 0;  // mean light in excess of exact PCF
  double error_chebyshev = 0, error_reduced = 0;                        // mean |v - exact PCF|
};

std::string describe(const Bleeding& b) {
  char text[300];
  std::snprintf(text, sizeof text,
                "mean excess light over exact PCF: Chebyshev %.4f, reduced %.4f, with the depth-range bound %.4f, "
                "both %.4f (mean |error| %.4f -> %.4f)",
                b.chebyshev, b.reduced, b.bounded, b.bounded_reduced, b.error_chebyshev, b.error_reduced);
  return text;
}

// observed < bound (strict) as a comparison with 0 within the float just below the bound; or
// observed <= bound as the excess max(0, observed - bound) compared exactly with 0.
CaseResult at_most(const std::string& name, double observed, double bound, bool strict) {
  Image e(1, 1), o(1, 1);
  if (!strict) {
    o.at(0, 0) = static_cast<float>(std::max(0.0, observed - bound));
    return {name, Tolerance::exact(), compare(e, o, Tolerance::exact())};
  }
  o.at(0, 0) = static_cast<float>(observed);
  const double b = std::nextafter(static_cast<float>(bound), 0.0f);  // compared as floats (Image)
  return {name, Tolerance::absolute(b), compare(e, o, Tolerance::absolute(b))};
}

void bleeding_cases(const Gpu& gpu, const VsmParams& params, std::vector<CaseResult>& results) {
  const auto& f = fixtures::kTwoOccluders;
  const Image depth = generate_two_occluders(f);
  std::vector<VsmQuery> queries;
  for (int y = 0; y < f.size; ++y)
    for (int x = 0; x < f.size; ++x) queries.push_back({x, y, f.plane_depth, f.bias});
  VsmParams none = params;
  none.bleeding_reduction = 0.0f;
  const std::vector<Query> reduced = gpu.run(depth, queries, params).results;
  const std::vector<Query> plain = gpu.run(depth, queries, none).results;
  Bleeding b;
  for (size_t k = 0; k < queries.size(); ++k) {
    const double exact = gaussian_pcf_visibility(depth, queries[k].x, queries[k].y, f.plane_depth - f.bias, params.blur);
    const auto excess = [&](float v) { return std::max(0.0, v - exact); };
    b.chebyshev += excess(plain[k][1]);
    b.reduced += excess(reduced[k][2]);
    b.bounded += excess(plain[k][0]);
    b.bounded_reduced += excess(reduced[k][0]);
    b.error_chebyshev += std::fabs(plain[k][1] - exact);
    b.error_reduced += std::fabs(reduced[k][0] - exact);
  }
  const double count = static_cast<double>(queries.size());
  for (double* v : {&b.chebyshev, &b.reduced, &b.bounded, &b.bounded_reduced, &b.error_chebyshev, &b.error_reduced})
    *v /= count;
  const std::string label = std::string(f.name) + " " + vsm_kind_name(params.kind) + " light bleeding (" + describe(b) + ")";
  results.push_back(at_most(label + ": the reduction lowers the Chebyshev bound's excess (below it)", b.reduced,
                            b.chebyshev, true));
  results.push_back(at_most(label + ": the depth-range bound does not raise it (excess over it 0)", b.bounded,
                            b.chebyshev, false));
  results.push_back(at_most(label + ": reduction and bound together lower it (below it)", b.bounded_reduced,
                            b.chebyshev, true));
}

}  // namespace

std::vector<CaseResult> run_vsm_check(const CheckEnvironment& env) {
  const Gpu gpu{env, VsmMomentsPass(env.device, env.tree), VsmQueryPass(env.device, env.tree),
                DepthPyramidBuilder(env.device, env.tree)};
  std::vector<CaseResult> results;
  const std::vector<Map> all = maps(env);
  for (VsmKind kind : kKinds) {
    const VsmParams params = params_for(kind);
    for (const Map& map : all) map_cases(gpu, map, params, results);
    bleeding_cases(gpu, params, results);
  }
  // Radius 0 (no blur; the depth-range bound over the receiver's texel alone: `vsm:radius=0`, the
  // cascades bench's configuration), VSM on the noise and step-edge maps.
  VsmParams unblurred = params_for(VsmKind::vsm);
  unblurred.blur.radius = 0;
  for (const Map& map : all)
    if (map.name.rfind("noise ", 0) == 0 || map.name.rfind("step_edge ", 0) == 0) map_cases(gpu, map, unblurred, results);
  return results;
}

}  // namespace pn
