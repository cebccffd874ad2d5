// Cases of the depth_cache check (issue 13):
//  - depth_cache.glsl's composition and shadow test over pairs of fixture maps (NaN and ±Inf among
//    them) at every texel against the definition, and receivers at, just in front of and just
//    behind the composed depth, NaN and +Inf ones, with and without a bias: exact;
//  - the compose pass over a texel list: the listed texels composed, every other texel untouched;
//  - motion sequences of the animated scene through both caches: every frame's composed map equals
//    a full render of the frame texel for texel, the incrementally kept min/max mip chain and
//    pyramid equal full rebuilds from that render (exact: the same operations on the same texels;
//    the pyramid every 5th frame, it is 16 · N² · levels bytes to read back), and Fast PCSS on the
//    cached source equals Fast PCSS on the full render every 10th frame.
#include "check/depth_cache_check.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <utility>

#include "core/format.h"
#include "core/seeded_random.h"
#include "fixture_images/texture_fixture.h"
#include "device/texel_list.h"
#include "pass_runners/depth_cache_pass.h"
#include "pass_runners/gbuffer_pass.h"
#include "pass_runners/shadow_map_pass.h"
#include "pipeline/pcss_pipeline.h"
#include "reference/depth_cache_reference.h"
#include "scene/animated_scene.h"
#include "frame/shadow_map_source.h"
#include "technique/shadow_map_sources.h"

namespace pn {
namespace {

constexpr int kFixtureWidth = 37, kFixtureHeight = 29;
constexpr int kFastScreen = 128;
constexpr int kPyramidEvery = 5, kFastEvery = 10;

// Tracks the worst of many comparisons under one tolerance, and the frame it came from.
struct Worst {
  Comparison comparison;
  int frame = -1;
  bool seen = false;
  void add(const Comparison& c, int f) {
    const bool worse = !seen || (comparison.pass && !c.pass) ||
                       (c.pass == comparison.pass && c.worst_error > comparison.worst_error);
    if (worse) comparison = c, frame = f;
    seen = true;
  }
};

void module_cases(const CheckEnvironment& env, std::vector<CaseResult>& results) {
  const DepthCacheQueryPass pass(env.device, env.tree);
  const std::vector<fixtures::TextureFixture> fx = check_texture_fixtures(env);
  const size_t count = fx.size();
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  for (size_t i = 0; i < count; ++i)
    for (size_t j : {i, (i + 3) % count}) {
      const Image a = generate_fixture(fx[i], kFixtureWidth, kFixtureHeight);
      const Image b = generate_fixture(fx[j], kFixtureWidth, kFixtureHeight);
      const std::unique_ptr<DeviceTexture> ta = env.device.upload(a), tb = env.device.upload(b);
      const Image composed = depth_cache_compose_reference(a, b);
      std::vector<DepthCacheQuery> queries;
      for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
          const float c = composed.at(x, y);
          const float finite = std::isfinite(c) ? c : 1.0f;
          for (float r : {c, std::nextafter(finite, inf), std::nextafter(finite, -inf), nan, inf})
            for (float bias : {0.0f, 0.0125f}) queries.push_back({x, y, r, bias});
        }
      const std::vector<DepthCacheResult> got = pass.run(*ta, *tb, queries);
      Image expected(static_cast<int>(queries.size()), 1, 2), observed(static_cast<int>(queries.size()), 1, 2);
      for (size_t k = 0; k < queries.size(); ++k) {
        const DepthCacheQuery& q = queries[k];
        const float c = composed.at(q.u, q.v);
        expected.at(static_cast<int>(k), 0, 0) = c;
        expected.at(static_cast<int>(k), 0, 1) = depth_cache_visibility_reference(c, q.receiver_depth, q.bias);
        observed.at(static_cast<int>(k), 0, 0) = got[k].composed;
        observed.at(static_cast<int>(k), 0, 1) = got[k].visibility;
      }
      results.push_back({std::string("static ") + fx[i].name + ", dynamic " + fx[j].name + " " +
                             std::to_string(kFixtureWidth) + "x" + std::to_string(kFixtureHeight) +
                             ": [0] composed, [1] visibility of receivers at, beside, NaN and +Inf (bias 0, 0.0125)",
                         Tolerance::exact(), compare(expected, observed, Tolerance::exact())});
    }
  // Maps of unequal sizes (37x29 and 29x37): a texel is clamped into both (the smaller extent on each
  // axis, 29x29), never read out of either; texels off every edge too.
  // (The same two fixtures whatever subset --quick runs: the case's name is one on every API.)
  const auto& all = fixtures::kTextureFixtures;
  const Image a = generate_fixture(all[0], kFixtureWidth, kFixtureHeight);
  const Image b = generate_fixture(all[std::size(all) - 1], kFixtureHeight, kFixtureWidth);
  const std::unique_ptr<DeviceTexture> ta = env.device.upload(a), tb = env.device.upload(b);
  const int last = std::min(kFixtureWidth, kFixtureHeight) - 1;
  std::vector<DepthCacheQuery> queries;
  std::vector<float> expected_composed;
  for (int y = -3; y <= kFixtureWidth + 3; ++y)
    for (int x = -3; x <= kFixtureWidth + 3; ++x) {
      const int cx = std::clamp(x, 0, last), cy = std::clamp(y, 0, last);
      const float c = depth_cache_compose_reference(a.at(cx, cy), b.at(cx, cy));
      queries.push_back({x, y, c, 0.0f});
      expected_composed.push_back(c);
    }
  const std::vector<DepthCacheResult> got = pass.run(*ta, *tb, queries);
  Image expected(static_cast<int>(queries.size()), 1, 1), observed(static_cast<int>(queries.size()), 1, 1);
  for (size_t k = 0; k < queries.size(); ++k)
    expected.at(static_cast<int>(k), 0) = expected_composed[k], observed.at(static_cast<int>(k), 0) = got[k].composed;
  results.push_back({std::string("static ") + all[0].name + " 37x29, dynamic " + all[std::size(all) - 1].name +
                         " 29x37: composed at texels -3..40, clamped into both maps (29x29)",
                     Tolerance::exact(), compare(expected, observed, Tolerance::exact())});
}

void compose_pass_cases(const CheckEnvironment& env, std::vector<CaseResult>& results) {
  const DepthCacheComposer composer(env.device, env.tree);
  const int n = 70;
  const Image a = generate_fixture(fixtures::kTextureFixtures[std::size(fixtures::kTextureFixtures) - 1], n, n);
  const Image b = generate_fixture(fixtures::kTextureFixtures[std::size(fixtures::kTextureFixtures) - 2], n, n);
  const std::unique_ptr<DeviceTexture> ta = env.device.upload(a), tb = env.device.upload(b);
  const Image composed = depth_cache_compose_reference(a, b);
  constexpr float kUntouched = -7.0f;
  SeededRandom random(0x5eed0133u);
  for (int rects = 0; rects <= 6; rects += 3) {
    std::vector<TexelRect> list;
    for (int r = 0; r < rects; ++r) {
      const int x = random.uniform_int(-5, n), y = random.uniform_int(-5, n);
      list.push_back({x, y, x + random.uniform_int(1, 25), y + random.uniform_int(1, 25)});
    }
    const std::unique_ptr<DeviceTexture> target = env.device.upload(Image(n, n, 1, kUntouched));
    TexelList texels;
    const TexelRun run = texels.add(list, n, n);  // overlapping rectangles list a texel twice: harmless
    texels.upload(env.device);
    if (rects == 0) composer.compose(*ta, *tb, *target, n);  // no list: the whole map
    else composer.compose(*ta, *tb, *target, n, run, &texels);
    Image expected(n, n, 1, kUntouched);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        bool written = rects == 0;
        for (const TexelRect& r : list) written = written || (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1);
        if (written) expected.at(x, y) = composed.at(x, y);
      }
    results.push_back({"compose pass " + std::to_string(n) + "x" + std::to_string(n) + ", " +
                           (rects == 0 ? std::string("whole map") : std::to_string(rects) + " seeded rectangles' texels") +
                           ": composed there, untouched elsewhere",
                       Tolerance::exact(), compare(expected, env.device.read_texture(*target), Tolerance::exact())});
  }
}

// What the sequence exercised, counted from the scenes themselves.
struct MotionEvents {
  int starts = 0, stops = 0, exits = 0, crossings = 0;
};

bool outside_map(const Box& b) {
  const float edge = 12.0f;  // beyond the light's frustum at the ground (±11.5)
  return b.lo.x > edge || b.hi.x < -edge || b.lo.z > edge || b.hi.z < -edge;
}

}  // namespace

std::vector<CaseResult> run_motion_sequence(const CheckEnvironment& env, const MotionSequence& sequence) {
  const QueryDevice& context = env.device;
  const int n = sequence.map_size;
  const std::filesystem::path model = animated_scene_model("");
  AnimatedScene animation(find_animated_scene_fixture("moving"), sequence.k, n, model);
  SourceOptions options = sequence.options;
  options.mip_chain = true;
  options.pyramid_max_level = 31;
  const auto cache = find_shadow_map_source(sequence.source).make(context, env.tree, options);
  const ShadowMapRenderer full(context, env.tree);
  const MinMaxMipBuilder mip_builder(context, env.tree);
  const DepthPyramidBuilder pyramid_builder(context, env.tree);
  const GBufferRenderer gbuffers(context, env.tree);
  const PcssPipeline pipeline(context, env.tree);
  const Tolerance exact = Tolerance::exact();

  Worst map, mip, pyramid, fast;
  MotionEvents events;
  Scene previous;
  std::vector<bool> was_moving, was_outside;
  for (int f = 0; f < sequence.frames; ++f) {
    const Scene scene = animation.frame(f);
    const SourcedMap& cached = cache->render(scene);
    const std::unique_ptr<DeviceTexture> reference = full.render_texture(scene, scene.map_light());
    map.add(compare(context.read_texture(*reference, 0, 0), context.read_texture(*cached.map, 0, 0), exact), f);

    const MinMaxMipChain rebuilt = mip_builder.build(*reference, n);
    for (int level = rebuilt.first_level; level <= rebuilt.top_level; ++level)
      mip.add(compare(read_mip_chain_level(context, rebuilt, level), read_mip_chain_level(context, *cached.mip, level), exact), f);
    if (f % kPyramidEvery == 0 || f + 1 == sequence.frames) {
      const DepthPyramid whole = pyramid_builder.build(*reference, n, n, 31);
      for (int level = 0; level < whole.levels; ++level)
        pyramid.add(compare(read_pyramid_level(context, whole, level), read_pyramid_level(context, *cached.pyramid, level), exact), f);
    }
    if (f % kFastEvery == kFastEvery - 1) {
      const std::unique_ptr<DeviceTexture> gbuffer =
          gbuffers.render_texture(scene, kFastScreen, fixtures::kNormalOffsetTexels, scene.map_light());
      const TechniqueInputs on_cache{scene.light, kFastScreen, cached.map, gbuffer.get(), cached.mip, cached.pyramid};
      const TechniqueInputs on_full{scene.light, kFastScreen, reference.get(), gbuffer.get()};
      const Image a = context.read_texture(pipeline.run(on_full, fast_pcss()).soft_shadow(), 0, 0);
      const Image b = context.read_texture(pipeline.run(on_cache, fast_pcss()).soft_shadow(), 0, 0);
      fast.add(compare(a, b, exact), f);
    }

    // Events: starts and stops (transforms), boxes leaving the map, pairs of moving boxes that overlap.
    std::vector<bool> moving(scene.objects.size(), false), outside(scene.boxes.size(), false);
    for (size_t o = 0; f > 0 && o < scene.objects.size(); ++o) moving[o] = scene.objects[o].transform != previous.objects[o].transform;
    for (size_t o = 0; f > 1 && o < moving.size(); ++o) events.starts += moving[o] && !was_moving[o], events.stops += !moving[o] && was_moving[o];
    for (size_t b = 1; b < scene.boxes.size(); ++b) {
      outside[b] = outside_map(scene.boxes[b]);
      if (f > 0 && outside[b] && !was_outside[b]) ++events.exits;
      for (size_t c = b + 1; c < scene.boxes.size(); ++c) {
        const Box& p = scene.boxes[b];
        const Box& q = scene.boxes[c];
        if ((moving[b] || moving[c]) && p.lo.x < q.hi.x && q.lo.x < p.hi.x && p.lo.z < q.hi.z && q.lo.z < p.hi.z) ++events.crossings;
      }
    }
    was_moving = moving, was_outside = outside, previous = scene;
  }

  const std::string scene_name = model.empty() ? "moving' (boxes only: " + std::string(fixtures::kAnimatedModel) + " not found)"
                                               : "moving' with " + model.filename().string();
  const std::string name = sequence.source + " cache, '" + scene_name + ", K = " + format_number("%g", sequence.k) +
                           ", " + std::to_string(sequence.frames) + " frames at " + std::to_string(n) + "² (" +
                           std::to_string(events.starts) + " starts, " + std::to_string(events.stops) + " stops, " +
                           std::to_string(events.exits) + " exits from the map, " + std::to_string(events.crossings) +
                           " box-frames overlapping a moving box)";
  const auto worst_at = [](const Worst& w) { return " (worst at frame " + std::to_string(w.frame) + ")"; };
  std::vector<CaseResult> out;
  out.push_back({name + ": composed map == full render, every frame" + worst_at(map), exact, map.comparison});
  out.push_back({name + ": min/max mip chain kept == rebuilt from the full render, every level and frame" + worst_at(mip), exact, mip.comparison});
  out.push_back({name + ": pyramid kept == rebuilt (min, max, mean), every level, every " + std::to_string(kPyramidEvery) +
                     "th frame" + worst_at(pyramid), exact, pyramid.comparison});
  out.push_back({name + ": Fast PCSS on the cache == on the full render, " + std::to_string(kFastScreen) + "², every " +
                     std::to_string(kFastEvery) + "th frame" + worst_at(fast), exact, fast.comparison});
  return out;
}

std::vector<CaseResult> run_depth_cache_check(const CheckEnvironment& env) {
  std::vector<CaseResult> results;
  module_cases(env, results);
  compose_pass_cases(env, results);
  for (const auto& [source, k] : {std::pair{"two-map", 0.3}, std::pair{"dirty-rect", 0.3}, std::pair{"dirty-rect", 1.0}}) {
    MotionSequence s;
    s.source = source;
    s.k = k;
    if (env.options.quick && k != 0.3) continue;  // the dirty-rectangle cache's programs ran at K = 0.3
    const std::vector<CaseResult> cases = run_motion_sequence(env, s);
    results.insert(results.end(), cases.begin(), cases.end());
  }
  return results;
}

}  // namespace pn
