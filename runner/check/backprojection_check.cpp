// Cases of the backprojection check (issue 28): backprojection.glsl's one call
// (pnBackprojectionWork, as passes/backprojection_query.comp runs it) against
// the CPU's rays through the map's surface (reference/backprojection_reference.h):
// - every texel resolved (tolerance 0, the budget never reached), the gap rule's
//   default: each scene's own map and G-buffer receivers, an area light, 8 × 8
//   samples, and the light 4 times as wide — exactly the reference's
//   visibility, the samples within rounding of a verdict left open (counted);
//   4 × 4 and 16 × 16 samples and a thickness of 0.5 on the boxes;
// - a 256² map under the tall blocker with the light 4 times as wide: thousands
//   of texels a receiver (llvmpipe's loop limit, backprojection.h), exact;
// - the sun (an orthographic map of spread S) over a random height field:
//   likewise exact, at 8 × 8 samples and at 16 × 16 with a thickness of 0.5;
// - a point light (width 0): the hard shadow of the receiver's own texel;
// - the defaults (nodes of a tight depth range as one patch, the budget):
//   within the stated bound of the exact visibility;
// - a budget of 16 nodes: finite, in [0, 1], at most budget + stack nodes —
//   the rest estimated, never dropped;
// - two layers (issue 42, the overload with the second layer): every scene's
//   map with its back-face layer, the scene's light and 4 times as wide, and the
//   sun over the random height field with a random second layer (thick,
//   +Inf, NaN, nearer than the first) — exactly the CPU's rays against the
//   slabs; the defaults over the back-face layer within the stated bound.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "backprojection.h"
#include "check/device_scene.h"
#include "check/module_check.h"
#include "core/format.h"
#include "core/seeded_random.h"
#include "pass_runners/backprojection_pass.h"
#include "pass_runners/minmax_mip_pass.h"
#include "pass_runners/shadow_map_pass.h"
#include "reference/backprojection_reference.h"
#include "scene/scene.h"
#include "scenes.h"

namespace pn {
namespace {

constexpr int kMap = 64, kScreen = 32;  // the reference is brute force: N² texels × samples a receiver
// The fence's rails and posts are 0.1 and 0.12 wide: a 64² map over its 20-unit ground (texels
// 0.3 wide) sees neither, and every receiver would be lit. At 256² the map holds them.
constexpr int kFenceMap = 256;
constexpr float kBias = 0.02f;
// The defaults' patches against the exact visibility: mean and largest difference allowed
// (measured on these scenes: docs/modules/backprojection.md).
constexpr double kPatchMeanBound = 0.02, kPatchMaxBound = 0.25;

struct Receivers {
  std::vector<BackprojectionQuery> queries;
  std::vector<int> pixels;  // screen pixel of each (y · size + x)
};

// Every `every`-th pixel of the G-buffer that sees a surface, as a receiver.
Receivers gbuffer_receivers(const Image& gbuffer, int side, float tolerance, int budget,
                            float thickness = static_cast<float>(PN_BACKPROJECTION_DEFAULT_THICKNESS), int every = 1) {
  Receivers r;
  int seen = 0;
  for (int y = 0; y < gbuffer.height; ++y)
    for (int x = 0; x < gbuffer.width; ++x) {
      if (gbuffer.at(x, y, 3) == 0.0f || seen++ % every != 0) continue;
      BackprojectionQuery q{gbuffer.at(x, y, 0), gbuffer.at(x, y, 1), gbuffer.at(x, y, 2), kBias, side, tolerance, budget};
      q.thickness = thickness;
      r.queries.push_back(q);
      r.pixels.push_back(y * gbuffer.width + x);
    }
  return r;
}

// The GPU's visibilities inside the reference's intervals (exact but for the ambiguous samples):
// the rays through the map's surface, or with `second` (the second layer), against its slabs.
CaseResult exact_case(const std::string& name, const Image& map, const LightModel& light,
                      const std::vector<BackprojectionQuery>& queries, const std::vector<BackprojectionResult>& got,
                      const Image* second = nullptr) {
  BoundedElements elements;
  int ambiguous = 0, umbra = 0, penumbra = 0;
  for (size_t k = 0; k < queries.size(); ++k) {
    const BackprojectionQuery& q = queries[k];
    const BackprojectionBounds b =
        second != nullptr ? backprojection_slab_reference(map, *second, light, q.u, q.v, q.depth, q.bias, q.side)
                          : backprojection_reference(map, light, q.u, q.v, q.depth, q.bias, q.side, q.gap, q.thickness);
    ambiguous += b.ambiguous;
    umbra += b.visibility_hi == 0.0 ? 1 : 0;
    penumbra += b.visibility_hi > 0.0 && b.visibility_lo < 1.0 ? 1 : 0;
    elements.add_interval(b.visibility_lo, b.visibility_hi, got[k].visibility, static_cast<int>(k), 0);
  }
  Tolerance tolerance = Tolerance::absolute(0.0);
  const Comparison c = compare_bounded(elements, tolerance);
  return {name + " (" + std::to_string(queries.size()) + " receivers, " + std::to_string(umbra) + " in the umbra, " +
              std::to_string(penumbra) + " in a penumbra, receiver k at (k, 0); " +
              std::to_string(ambiguous) + " samples within rounding of a verdict left open)",
          tolerance, c};
}

// The defaults (tight nodes as one patch, the budget) against every texel resolved, on the same
// receivers: within the stated mean and largest difference.
CaseResult defaults_case(const std::string& what, const std::vector<BackprojectionResult>& got,
                         const std::vector<BackprojectionResult>& approximate) {
  double sum = 0.0, worst = 0.0, nodes_exact = 0.0, nodes_patched = 0.0;
  for (size_t k = 0; k < got.size(); ++k) {
    const double e = std::fabs(static_cast<double>(approximate[k].visibility) - got[k].visibility);
    sum += e, worst = std::max(worst, e);
    nodes_exact += got[k].nodes, nodes_patched += approximate[k].nodes;
  }
  const double receivers = static_cast<double>(std::max<size_t>(1, got.size()));
  const double mean = sum / receivers;
  const std::string measured = "mean " + format_number("%.4f", mean) + ", largest " + format_number("%.4f", worst) +
                               "; nodes a receiver " + format_number("%.1f", nodes_patched / receivers) + " vs " +
                               format_number("%.1f", nodes_exact / receivers) + " resolved";
  Image e(2, 1), o(2, 1);
  o.at(0, 0) = static_cast<float>(mean), o.at(1, 0) = static_cast<float>(worst);
  e.at(0, 0) = static_cast<float>(std::min(mean, kPatchMeanBound));
  e.at(1, 0) = static_cast<float>(std::min(worst, kPatchMaxBound));
  CaseResult bound{what + ": the defaults (tolerance " + format_number("%g", PN_BACKPROJECTION_DEFAULT_TOLERANCE) +
                       ", budget " + std::to_string(PN_BACKPROJECTION_DEFAULT_BUDGET) +
                       ") vs every texel resolved: [0] mean difference <= " + format_number("%g", kPatchMeanBound) +
                       ", [1] largest <= " + format_number("%g", kPatchMaxBound) + " (" + measured + ")",
                   Tolerance::exact(), compare(e, o, Tolerance::exact())};
  bound.headline = true;
  return bound;
}

}  // namespace

std::vector<CaseResult> run_backprojection_check(const CheckEnvironment& env) {
  const BackprojectionQueryPass pass(env.device, env.tree);
  const MinMaxMipBuilder mips(env.device, env.tree);
  const ShadowMapRenderer back_faces(env.device, env.tree, MapLayer::back_faces);
  std::vector<CaseResult> results;
  const auto read = [&](const DeviceTexture& t) { return env.device.read_texture(t, 0, 0); };

  for (const auto& fixture : fixtures::kScenes) {
    const int n = fixture.kind == fixtures::SceneKind::fence ? kFenceMap : kMap;
    const Scene scene = make_scene(fixture, n);
    const std::string name = std::string(fixture.name) + " " + std::to_string(n) + "² map, " +
                             std::to_string(kScreen) + "² screen";
    const DeviceSceneFrame frame = render_device_frame(env, scene, kScreen);
    const Image map = read(*frame.shadow_map), gbuffer = read(*frame.gbuffer);
    const MinMaxMipChain mip = mips.build(*frame.shadow_map, n);
    const bool first = &fixture == &fixtures::kScenes[0];
    // The scene's light, and 4 times as wide (penumbrae 4 times as wide: the G-buffer is the same).
    Scene wide = scene;
    wide.light.width *= 4.0;
    for (int side : first ? std::vector<int>{4, 8, 16, 0} : std::vector<int>{8, 0}) {
      const LightModel& light = side == 0 ? wide.light : scene.light;
      side = side == 0 ? 8 : side;
      const std::string what = name + (&light == &wide.light ? ", the light 4x as wide" : "") + ", " +
                               std::to_string(side) + "x" + std::to_string(side) + " samples";
      const Receivers exact = gbuffer_receivers(gbuffer, side, 0.0f, PN_BACKPROJECTION_MAX_BUDGET);
      const std::vector<BackprojectionResult> got = pass.run(mip, light, exact.queries);
      if (first && side == 4) {  // receivers with no depth to shade (0, behind the light, +Inf, NaN): lit
        std::vector<BackprojectionQuery> none;
        for (const float depth : {0.0f, -0.5f, std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()})
          for (size_t k = 0; k < exact.queries.size(); k += exact.queries.size() / 4 + 1) {
            none.push_back(exact.queries[k]);
            none.back().depth = depth;
          }
        results.push_back(exact_case(what + ", receivers at depth 0, -0.5, +Inf and NaN", map, light, none,
                                     pass.run(mip, light, none)));
      }
      results.push_back(exact_case(what + ", every texel resolved, vs the rays through the map's surface on the CPU", map,
                                   light, exact.queries, got));
      if (&light != &wide.light) continue;
      if (first) {  // silhouettes closed by walls half the way down to the receiver
        const Receivers thick = gbuffer_receivers(gbuffer, side, 0.0f, PN_BACKPROJECTION_MAX_BUDGET, 0.5f);
        results.push_back(exact_case(what + ", thickness 0.5, every texel resolved, vs the rays on the CPU", map, light,
                                     thick.queries, pass.run(mip, light, thick.queries)));
      }

      // The defaults: tight nodes as one patch, the budget.
      Receivers patched = gbuffer_receivers(gbuffer, side, PN_BACKPROJECTION_DEFAULT_TOLERANCE,
                                            PN_BACKPROJECTION_DEFAULT_BUDGET);
      const std::vector<BackprojectionResult> approximate = pass.run(mip, light, patched.queries);
      results.push_back(defaults_case(what, got, approximate));

      // A budget of 16 nodes: the rest stand as patches; never out of [0, 1], never past budget + stack.
      Receivers starved = gbuffer_receivers(gbuffer, side, 0.0f, 16);
      const std::vector<BackprojectionResult> short_run = pass.run(mip, light, starved.queries);
      Image se(static_cast<int>(short_run.size()), 1), so(static_cast<int>(short_run.size()), 1);
      for (size_t k = 0; k < short_run.size(); ++k) {
        const BackprojectionResult& r = short_run[k];
        const bool fine = std::isfinite(r.visibility) && r.visibility >= 0.0f && r.visibility <= 1.0f &&
                          r.nodes <= 16.0f + 48.0f;
        so.at(static_cast<int>(k), 0) = fine ? 1.0f : 0.0f, se.at(static_cast<int>(k), 0) = 1.0f;
      }
      results.push_back({what + ": budget 16 nodes: every visibility finite, in [0, 1], at most 64 nodes visited (1: holds)",
                         Tolerance::exact(), compare(se, so, Tolerance::exact())});
    }

    // Two layers (issue 42): the map's texels as slabs down to its back-face layer (the technique's
    // default), the scene's light and 4 times as wide.
    const std::unique_ptr<DeviceTexture> layer = back_faces.render_texture(scene, scene.map_light());
    const Image second = read(*layer);
    const MinMaxMipChain second_mip = mips.build(*layer, n);
    const Receivers slab_receivers = gbuffer_receivers(gbuffer, 8, 0.0f, PN_BACKPROJECTION_MAX_BUDGET);
    for (const LightModel* light : std::initializer_list<const LightModel*>{&scene.light, &wide.light}) {
      const std::string what = name + (light == &wide.light ? ", the light 4x as wide" : "") +
                               ", 8x8 samples, the back-face layer";
      const std::vector<BackprojectionResult> got = pass.run(mip, *light, slab_receivers.queries, &second_mip);
      results.push_back(exact_case(what + ": every texel a slab, vs the rays against the slabs on the CPU", map, *light,
                                   slab_receivers.queries, got, &second));
      if (light != &wide.light) continue;
      const Receivers patched = gbuffer_receivers(gbuffer, 8, PN_BACKPROJECTION_DEFAULT_TOLERANCE,
                                                  PN_BACKPROJECTION_DEFAULT_BUDGET);
      results.push_back(defaults_case(what, got, pass.run(mip, *light, patched.queries, &second_mip)));
    }

    // A point light: each receiver's own texel decides (a hard shadow).
    Scene point = scene;
    point.light.width = 0.0;
    const Receivers hard = gbuffer_receivers(gbuffer, 8, 0.0f, PN_BACKPROJECTION_MAX_BUDGET);
    const std::vector<BackprojectionResult> got = pass.run(mip, point.light, hard.queries);
    Image expected(static_cast<int>(got.size()), 1), observed(static_cast<int>(got.size()), 1);
    for (size_t k = 0; k < got.size(); ++k) {
      const BackprojectionQuery& q = hard.queries[k];
      const int x = std::clamp(static_cast<int>(std::floor(q.u)), 0, n - 1);
      const int y = std::clamp(static_cast<int>(std::floor(q.v)), 0, n - 1);
      const bool inside = q.u >= 0 && q.u < n && q.v >= 0 && q.v < n;
      expected.at(static_cast<int>(k), 0) = inside && map.at(x, y) + kBias < q.depth ? 0.0f : 1.0f;
      observed.at(static_cast<int>(k), 0) = got[k].visibility;
    }
    results.push_back({name + ", a point light: the receiver's own texel, a hard shadow", Tolerance::exact(),
                       compare(expected, observed, Tolerance::exact())});
  }

  // A 256² map under the tall blocker with the light 4 times as wide: thousands of texels a receiver,
  // past what the loops of a per-sample test could run on llvmpipe (one limit of 65535 loop
  // iterations an invocation, backprojection.h): every fourth receiver of a 64² screen, exact.
  {
    constexpr int kLargeMap = 256, kLargeScreen = 64;
    const Scene scene = make_scene(fixtures::kScenes[2], kLargeMap);
    Scene wide = scene;
    wide.light.width *= 4.0;
    const DeviceSceneFrame frame = render_device_frame(env, scene, kLargeScreen);
    const Image map = read(*frame.shadow_map), gbuffer = read(*frame.gbuffer);
    const MinMaxMipChain mip = mips.build(*frame.shadow_map, kLargeMap);
    const Receivers exact = gbuffer_receivers(gbuffer, 8, 0.0f, PN_BACKPROJECTION_MAX_BUDGET,
                                              static_cast<float>(PN_BACKPROJECTION_DEFAULT_THICKNESS), 4);
    const std::vector<BackprojectionResult> got = pass.run(mip, wide.light, exact.queries);
    double nodes = 0.0;
    for (const BackprojectionResult& r : got) nodes = std::max(nodes, static_cast<double>(r.nodes));
    results.push_back(exact_case(std::string(fixtures::kScenes[2].name) + " " + std::to_string(kLargeMap) + "² map, the light 4x as wide, "
                                 "8x8 samples, every texel resolved (up to " + format_number("%.0f", nodes) +
                                 " nodes a receiver), vs the rays on the CPU",
                                 map, wide.light, exact.queries, got));
  }

  // The sun over a random height field: an orthographic map, texels 0.1 wide, spread 0.05.
  {
    SeededRandom random(0x5eed0028u);
    LightModel sun;
    sun.width = 0.0, sun.spread = 0.05, sun.texel_world = 0.1, sun.near_plane = 1.0, sun.far_plane = 50.0;
    sun.map_size = kMap;
    Image map(kMap, kMap, 1, 20.0f);
    for (int b = 0; b < 24; ++b) {  // boxes of random heights (light depths 6..19), some floating
      const int x0 = random.uniform_int(0, kMap - 8), y0 = random.uniform_int(0, kMap - 8);
      const int w = random.uniform_int(1, 10), h = random.uniform_int(1, 10);
      const float d = random.uniform_float(6.0f, 19.0f);
      for (int y = y0; y < std::min(kMap, y0 + h); ++y)
        for (int x = x0; x < std::min(kMap, x0 + w); ++x) map.at(x, y) = std::min(map.at(x, y), d);
    }
    map.at(5, 5) = INFINITY, map.at(6, 5) = NAN;  // no occluder
    const std::unique_ptr<DeviceTexture> texture = env.device.upload(map);
    const MinMaxMipChain mip = mips.build(*texture, kMap);
    std::vector<BackprojectionQuery> queries;
    for (int k = 0; k < 600; ++k) {
      const float u = random.uniform_float(0.0f, kMap), v = random.uniform_float(0.0f, kMap);
      const int x = std::min(kMap - 1, static_cast<int>(u)), y = std::min(kMap - 1, static_cast<int>(v));
      const float depth = k % 3 == 0 ? random.uniform_float(6.0f, 21.0f) : (std::isfinite(map.at(x, y)) ? map.at(x, y) : 20.0f);
      queries.push_back({u, v, depth, kBias, 8, 0.0f, PN_BACKPROJECTION_MAX_BUDGET});
    }
    results.push_back(exact_case("the sun (orthographic, spread 0.05) over a random height field, 8x8 samples, every "
                                 "texel resolved, vs the rays on the CPU",
                                 map, sun, queries, pass.run(mip, sun, queries)));
    for (BackprojectionQuery& q : queries) q.thickness = 0.5f, q.side = 16;
    results.push_back(exact_case("the sun over the random height field, 16x16 samples, thickness 0.5, every texel "
                                 "resolved, vs the rays on the CPU",
                                 map, sun, queries, pass.run(mip, sun, queries)));
    // Its second layer: each box 0.2..6 deep; where nothing lies behind (+Inf, or NaN: the chain
    // reads a non-finite depth as +Inf) solid down to the receiver; a depth nearer than the first: flat.
    Image second(kMap, kMap, 1, INFINITY);
    for (int y = 0; y < kMap; ++y)
      for (int x = 0; x < kMap; ++x) {
        const float d = map.at(x, y), roll = random.uniform_float(0.0f, 1.0f);
        if (!(d < 20.0f)) continue;  // the ground: nothing behind it
        second.at(x, y) = roll < 0.05f ? NAN : roll < 0.1f ? d - 1.0f : roll < 0.15f ? INFINITY
                                                                                    : d + random.uniform_float(0.2f, 6.0f);
      }
    const std::unique_ptr<DeviceTexture> layer = env.device.upload(second);
    const MinMaxMipChain second_mip = mips.build(*layer, kMap);
    for (BackprojectionQuery& q : queries) q.side = 8;
    results.push_back(exact_case("the sun over the random height field with a random second layer, 8x8 samples: every "
                                 "texel a slab, vs the rays against the slabs on the CPU",
                                 map, sun, queries, pass.run(mip, sun, queries, &second_mip), &second));
  }
  return results;
}

}  // namespace pn
