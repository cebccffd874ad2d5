// The pcss_regions check's cases on the texture fixtures: search entries in every
// region mode and from the mip chain, the lit-coverage property, then filter
// entries and given entries (pcss_regions_check.cpp states the tolerances).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "check/pcss_regions_cases.h"
#include "core/seeded_random.h"
#include "fixture_images/texture_fixture.h"
#include "pass_runners/depth_pyramid_pass.h"
#include "pass_runners/minmax_mip_pass.h"

namespace pn::pcss_regions_cases {
namespace {

struct FixtureMap {
  std::string name;
  Image map;
  int max_level;
};

Image shifted_fixture(const char* name, int n) {
  Image map = generate_fixture(find_fixture(name), n, n);
  for (float& d : map.texels) d += kDepthShift;
  return map;
}

std::vector<FixtureMap> fixture_maps(const CheckEnvironment& env) {
  std::vector<FixtureMap> out;
  const std::string size = " " + std::to_string(kMapSize) + "²";
  for (const auto& f : check_texture_fixtures(env))
    out.push_back({f.name + size, shifted_fixture(f.name, kMapSize), 31});
  out.push_back({"boxes" + size + ", pyramid capped at level 2", shifted_fixture("boxes", kMapSize), 2});
  out.push_back({"noise 3²", shifted_fixture("noise", 3), 31});
  out.push_back({"step_edge 37²", shifted_fixture("step_edge", 37), 31});
  return out;
}

std::vector<RegionReceiver> fixture_receivers(const Image& map, std::uint32_t seed) {
  const int n = map.width;
  float lo = kInf, hi = -kInf;
  for (float d : map.texels)
    if (std::isfinite(d)) lo = std::min(lo, d), hi = std::max(hi, d);
  if (!(lo <= hi)) lo = hi = 1.5f;
  SeededRandom random(seed);
  std::vector<std::array<float, 2>> places;
  const float fn = static_cast<float>(n);
  for (int j = 0; j <= 10; ++j)
    for (int i = 0; i <= 10; ++i) places.push_back({-0.25f * fn + 0.15f * fn * i + 0.37f, -0.25f * fn + 0.15f * fn * j + 0.61f});
  for (int k = 0; k < 40; ++k) places.push_back({random.uniform_float(0.0f, fn), random.uniform_float(0.0f, fn)});
  const float half = static_cast<float>(n / 2);
  for (const auto& p : std::vector<std::array<float, 2>>{{half, half}, {half + 0.5f, 0.5f}, {0.0f, 0.0f}, {fn, fn}, {-0.5f, half}})
    places.push_back(p);
  std::vector<RegionReceiver> out;
  for (size_t k = 0; k < places.size(); ++k) {
    const float u = places[k][0], v = places[k][1];
    float local = 0.5f * (lo + hi);
    if (u >= 0 && v >= 0 && u < fn && v < fn) {
      const float d = map.at(static_cast<int>(u), static_cast<int>(v));
      if (std::isfinite(d)) local = d;
    }
    for (float d : {local, lo - 0.05f, hi + 0.05f, random.uniform_float(lo, hi), 0.25f}) out.push_back({u, v, d, 1.0f});
    if (k % 3 == 0) out.push_back({u, v, kNan, 1.0f});
    else if (k % 3 == 1) out.push_back({u, v, kInf, 1.0f});
    else out.push_back({u, v, 1.5f, 0.0f});  // no surface
  }
  return out;
}

// Filter queries from lit and unlit search entries, and given entries with odd sides and centres.
void synthetic_cases(std::vector<CaseResult>& results, const PcssRegionsQueryPass& pass, const DepthPyramid& pyramid,
                     int n) {
  for (const NamedLight& l : fixture_lights(n)) {
    std::vector<PcssRegionsQuery> queries;
    std::vector<RegionEntry> expected;
    int k = 0;
    for (float d : {0.25f, 0.5f, 0.9f, 1.5f, 2.1f, kInf, kNan})
      for (const auto& [x, y] : {std::pair{10.3f, 20.6f}, {-5.2f, 70.1f}})
        for (float s : {-1.0f, 3.7f, 0.0f})
          for (float mean : {0.25f, 0.5f, 0.5f * d, 0.75f * d, d * (1.0f - 1.0f / 1024.0f), d, 1.25f * d, 0.0f, -1.0f,
                             kNan, kInf})
            for (bool has : {true, false})
              for (float scale : {0.0f, 0.5f, 1.0f, 2.5f, -1.0f, kNan}) {
                PcssRegionsQuery q;
                q.kind = PcssRegionsQuery::Kind::filter, q.mode = kModes[k++ % 3], q.input = {d, x, y, s};
                q.blocker_mean = mean, q.has_blocker = has, q.filter_scale = scale;
                queries.push_back(q);
                expected.push_back(filter_entry(l.light, RegionEntry{d, x, y, s}, mean, has, scale));
              }
    const std::vector<PcssRegionsResult> observed = pass.run(pyramid, l.light, queries);
    EntryGroup g;
    for (size_t i = 0; i < queries.size(); ++i) {
      add_entry(g, expected[i], false, observed[i]);
      add_regions(g, observed[i], n, queries[i].mode);
    }
    push_group(results, "filter entries, " + l.name + ", N = " + std::to_string(n), g, "filter entries");
  }

  std::vector<PcssRegionsQuery> queries;
  const float fn = static_cast<float>(n);
  int k = 0;
  for (float s : {-1.0f, -0.0f, 0.0f, 0.3f, 0.5f, 1.0f, 1.5f, 2.5f, 3.49f, 7.3f, 16.0f, fn - 0.3f, fn, 100.0f, 4.0f * fn,
                  1e30f, kInf, -kInf, kNan})
    for (float x : {-70.0f, -3.3f, -0.5f, 0.0f, 0.25f, 0.5f, 7.0f, 12.5f, 31.99f, 32.0f, fn - 0.5f, fn, fn + 0.7f,
                    2.0f * fn + 2.0f, 1e30f, -1e30f, kInf, -kInf, kNan})
      for (float y : {-3.3f, 0.0f, 12.5f, fn - 0.5f, fn + 0.7f, kNan})
        for (RegionMode mode : kModes) {
          // An infinite centre with an infinite side makes region.glsl's Step 1 bound Inf - Inf:
          // undefined in region.glsl and its reference alike, so not asked here.
          if ((std::isinf(x) || std::isinf(y)) && s == kInf) continue;
          PcssRegionsQuery q;
          q.kind = PcssRegionsQuery::Kind::entry, q.mode = mode, q.input = {(k++ % 2) ? 1.5f : kNan, x, y, s};
          queries.push_back(q);
        }
  const std::vector<PcssRegionsResult> observed = pass.run(pyramid, fixture_lights(n).front().light, queries);
  EntryGroup g;
  for (size_t i = 0; i < queries.size(); ++i) add_regions(g, observed[i], n, queries[i].mode);
  push_group(results, "given entries (odd sides and centres), N = " + std::to_string(n), g, "entries");
}

// The blocker depth z whose window (light_model's blocker_window_texels, decreasing in z on
// (near, d)) is `target` texels for a receiver at depth d, by bisection.
float blocker_depth_for(const LightModel& light, double d, double target) {
  double lo = light.near_plane, hi = d;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (light.blocker_window_texels(d, mid) > target ? lo : hi) = mid;
  }
  return static_cast<float>(0.5 * (lo + hi));
}

// A staircase's searches against search_entry, as one group named with the most refinements the
// reference took (the mip chain's counted searches compare their refinements too).
void add_staircase_group(const DepthScan& scan, const LightModel& light, const RegionReceiver& receiver,
                         const std::vector<PcssRegionsQuery>& queries, const std::vector<PcssRegionsResult>& observed,
                         Structure structure, const std::string& name, std::vector<CaseResult>& results,
                         SearchTally& tally) {
  const bool counted = structure == Structure::mip;
  EntryGroup g;
  int most = 0;
  for (size_t k = 0; k < queries.size(); ++k) {
    Rounding rounding{kAmbiguity};
    int refinements = 0;
    const RegionEntry expected = search_entry(scan, light, receiver, 0.0, queries[k].iterations, &rounding,
                                              structure, &refinements);
    most = std::max(most, refinements);
    add_entry(g, expected, rounding.ambiguous, observed[k], counted ? refinements : -1);
  }
  tally.searched += g.queries, tally.left_out += g.left_out;
  push_group(results, name + " refining " + std::to_string(most) + " times (its bound: 16)", g,
             counted ? "search entries and refinements (8, 15, 16, 100 iterations)"
                     : "search entries (8, 15, 16, 100 iterations)");
}

// A staircase of depth about one receiver on which Step 3 refines every time its bound allows
// (PN_REFINE_MAX_ITERATIONS, 16) over the pyramid: nested squares Q_j of sides 36, 34, …, 4 (the
// sides T_j = 38.25 − 2j the refinements reach) about the receiver, the texels of Q_j outside
// Q_{j+1} at the depth z_j whose blocker window is T_{j+1} (light_model's, inverted by bisection),
// the map outside Q_1 at z_0: each refinement's square holds its ring's depth as its min, and the
// next side is 2 texels smaller. Searches of 8, 15, 16 and 100 iterations against search_entry,
// which takes min(iterations, 16) refinements here.
void staircase_case(const CheckEnvironment& env, const PcssRegionsQueryPass& pass, std::vector<CaseResult>& results,
                    SearchTally& tally) {
  constexpr int n = 64;
  constexpr int kSteps = kRefineMaxIterations;  // 16
  const LightModel light = fixture_lights(n)[1].light;  // light 1
  const RegionReceiver receiver{32.5f, 32.5f, 2.0f, 1.0f};
  const auto side_at = [](int j) { return 38.25 - 2.0 * j; };  // T_j
  const auto depth_for = [&](double target) { return blocker_depth_for(light, receiver.depth, target); };
  Image map(n, n, 1, depth_for(side_at(1)));  // z_0 outside Q_1
  for (int j = 1; j <= kSteps; ++j) {
    const Rect q = pcss_square(receiver.u, receiver.v, side_at(j), n, nullptr);
    const float z = depth_for(side_at(j + 1));
    for (int y = q.y; y < q.y + q.height; ++y)
      for (int x = q.x; x < q.x + q.width; ++x) map.at(x, y) = z;
  }
  const std::unique_ptr<DeviceTexture> texture = env.device.upload(map);
  const DepthPyramid pyramid = DepthPyramidBuilder(env.device, env.tree).build(*texture, n, n, 31);
  const DepthScan scan(map);
  std::vector<PcssRegionsQuery> queries;
  for (int iterations : {8, kSteps - 1, kSteps, 100}) {
    const std::vector<PcssRegionsQuery> q = search_queries({receiver}, RegionMode::exact, iterations, 0.0f);
    queries.insert(queries.end(), q.begin(), q.end());
  }
  add_staircase_group(scan, light, receiver, queries, pass.run(pyramid, light, queries), Structure::pyramid,
                      "staircase " + std::to_string(n) + "², the pyramid's search", results, tally);
}

// The same over the aligned mip chain (pnSearchEntryMip): a refinement reads the min over the aligned
// nodes that cover its square (mip_square_cover), so the squares shrink only where their covers
// do: on a 1024² map about (472.5, 472.5), the sides whose covers strictly nest, each the largest
// side below the last with a smaller cover (4096 — the whole map — 512, 434, 256, …, 7, 2: 16 reads),
// each ring's depth the one whose window is the next side (+ ¼), and a last side of 1.25: 16
// refinements, each a smaller side. Searches of 8, 15, 16 and 100 iterations against search_entry.
void mip_staircase_case(const CheckEnvironment& env, const PcssRegionsQueryPass& pass, std::vector<CaseResult>& results,
                        SearchTally& tally) {
  constexpr int n = 1024;
  const LightModel light = fixture_lights(n)[1].light;  // light 1
  const RegionReceiver receiver{472.5f, 472.5f, 2.0f, 1.0f};
  const auto depth_for = [&](double target) { return blocker_depth_for(light, receiver.depth, target); };
  const auto cover = [&](double side) { return mip_square_cover(pcss_square(receiver.u, receiver.v, side, n, nullptr), n); };
  const auto inside = [](const Rect& a, const Rect& b) {  // a strictly inside b
    return a.x >= b.x && a.y >= b.y && a.x + a.width <= b.x + b.width && a.y + a.height <= b.y + b.height &&
           (a.width < b.width || a.height < b.height);
  };
  std::vector<int> sides;  // the squares read after the first (the search width's)
  Rect current = cover(light.search_width_texels(receiver.depth));
  std::vector<Rect> covers{current};
  for (int m = n; m >= 1; --m)
    if (inside(cover(m), current) && (sides.empty() || m < sides.back())) {
      sides.push_back(m), current = cover(m), covers.push_back(current);
      if (sides.size() + 1 == static_cast<size_t>(kRefineMaxIterations)) break;
    }
  // Ring j (in cover j, not in cover j + 1) at the depth whose window is square j + 1's side + ¼.
  Image map(n, n);
  for (size_t j = 0; j < covers.size(); ++j) {
    const float z = depth_for(j < sides.size() ? sides[j] + 0.25 : 1.25);
    const Rect& c = covers[j];
    for (int y = c.y; y < c.y + c.height; ++y)
      for (int x = c.x; x < c.x + c.width; ++x) map.at(x, y) = z;
  }
  const std::unique_ptr<DeviceTexture> texture = env.device.upload(map);
  const DepthPyramid pyramid = DepthPyramidBuilder(env.device, env.tree).build(*texture, n, n, 31);
  const MinMaxMipChain mip = MinMaxMipBuilder(env.device, env.tree).build(*texture, n);
  const DepthScan scan(map);
  std::vector<PcssRegionsQuery> queries;
  for (int iterations : {8, kRefineMaxIterations - 1, kRefineMaxIterations, 100})
    for (PcssRegionsQuery::Kind kind : {PcssRegionsQuery::Kind::search_mip_counted, PcssRegionsQuery::Kind::search_mip_plane}) {
      PcssRegionsQuery q = search_queries({receiver}, RegionMode::exact, iterations, 0.0f, Structure::mip).front();
      q.kind = kind;  // the plane's gradient 0: the counted search again, through the plane's call
      queries.push_back(q);
    }
  add_staircase_group(scan, light, receiver, queries, pass.run(pyramid, light, queries, &mip), Structure::mip,
                      "staircase " + std::to_string(n) + "², the mip chain's search", results, tally);
}

}  // namespace

void fixture_cases(const CheckEnvironment& env, const PcssRegionsQueryPass& pass, std::vector<CaseResult>& results,
                   SearchTally& tally) {
  const DepthPyramidBuilder builder(env.device, env.tree);
  const MinMaxMipBuilder mip_builder(env.device, env.tree);
  std::string counts, refining;  // "0/1/8/100", "1/8/100"
  for (int i : iteration_counts()) {
    counts += (counts.empty() ? "" : "/") + std::to_string(i);
    if (i > 0) refining += (refining.empty() ? "" : "/") + std::to_string(i);
  }
  std::uint32_t seed = 0x5eed0010u;
  bool first = true;
  for (const FixtureMap& f : fixture_maps(env)) {
    const int n = f.map.width;
    const std::unique_ptr<DeviceTexture> texture = env.device.upload(f.map);
    const DepthPyramid pyramid = builder.build(*texture, n, n, f.max_level);
    const MinMaxMipChain mip = mip_builder.build(*texture, n);
    const DepthScan scan(f.map);
    const std::vector<RegionReceiver> receivers = fixture_receivers(f.map, seed++);
    EntryGroup groups[4];  // the three region modes over the pyramid, then the mip chain's search
    LitCoverage coverage;
    std::vector<float> violations;
    for (const NamedLight& l : fixture_lights(n)) {
      std::vector<PcssRegionsQuery> queries;
      for (RegionMode mode : kModes)
        for (int iterations : iteration_counts())
          for (float bias : kBiases) {
            const std::vector<PcssRegionsQuery> q = search_queries(receivers, mode, iterations, bias);
            queries.insert(queries.end(), q.begin(), q.end());
          }
      for (int iterations : iteration_counts())
        for (float bias : kBiases) {
          const std::vector<PcssRegionsQuery> q = search_queries(receivers, RegionMode::exact, iterations, bias, Structure::mip);
          queries.insert(queries.end(), q.begin(), q.end());
        }
      const std::vector<PcssRegionsResult> observed = pass.run(pyramid, l.light, queries, &mip);
      for (size_t k = 0; k < queries.size(); ++k) {
        const PcssRegionsQuery& q = queries[k];
        const RegionReceiver& r = receivers[k % receivers.size()];
        const bool counted = q.kind == PcssRegionsQuery::Kind::search_mip_counted;
        const bool from_mip = q.kind == PcssRegionsQuery::Kind::search_mip || counted;
        Rounding rounding{kAmbiguity};
        int refinements = 0;
        const RegionEntry expected = search_entry(scan, l.light, r, q.bias, q.iterations, &rounding,
                                                  from_mip ? Structure::mip : Structure::pyramid, &refinements);
        EntryGroup& g = groups[from_mip ? 3 : static_cast<int>(q.mode)];
        add_entry(g, expected, rounding.ambiguous, observed[k], counted ? refinements : -1);
        add_regions(g, observed[k], n, q.mode);
        if (q.iterations > 0)  // the property: every mode, refining count and bias
          count_receiver(coverage, violations, r, observed[k],
                         [&] { return shadowing_truth(scan, l.light, r, q.bias); }, false);
      }
    }
    for (RegionMode mode : kModes) {
      const EntryGroup& g = groups[static_cast<int>(mode)];
      tally.searched += g.queries, tally.left_out += g.left_out;
      push_group(results, f.name + ", " + mode_name(mode), g,
                 ("search entries (3 lights, " + counts + " iterations, bias 0/0.01)").c_str());
    }
    tally.searched += groups[3].queries, tally.left_out += groups[3].left_out;
    push_group(results, f.name + ", from the mip chain (pnSearchEntryMip and …Counted), exact region", groups[3],
               ("search entries (3 lights, " + counts + " iterations, bias 0/0.01)").c_str());
    results.push_back(property_case(f.name + ", every region mode and the mip chain, " + refining + " iterations",
                                    violations, coverage, ""));
    if (first) synthetic_cases(results, pass, pyramid, n);
    first = false;
  }
  staircase_case(env, pass, results, tally);
  mip_staircase_case(env, pass, results, tally);
}

}  // namespace pn::pcss_regions_cases
