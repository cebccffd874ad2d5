// Cases of the traversal check (each comparison also reads the module's own
// pnTraversalBlockerMean and pnTraversalOccludedFraction of the GPU's counts
// against the expected counts' mean and fraction):
// - leaf side 1 (exact): occluder counts equal brute force exactly and the
//   blocker mean to float rounding, for power-of-two windows of side 1…256
//   and for exact (non-power-of-two) regions, on every fixture, with
//   receivers below, at the min of, inside, at the max of and above each
//   region's depth range;
// - sampled and HQEPCSS (min) leaves, leaf sides 2…16: equal to the CPU
//   recursion with the same table and decisions (nodes, fetches and counts
//   exactly, blocker mean to float rounding);
// - leaf side 1 over both structures with a receiver plane (pn_traverseRegionPlane,
//   pnTraverseRegionMipPlane):
//   occluders and depth sum within the interval the brute-force definition in
//   double leaves open to float rounding (texels within a band of their own
//   threshold), shallow to steep gradients, the plane's centre inside and far
//   outside the region; the open texels stay under 1 %;
// - leaf side 1 over squares with area-weighted edges (issue 51: pnRegionArea;
//   pnTraverseAreaMipPlane with the table's sums, pnTraverseAreaPlane over the
//   pyramid) against every texel's overlap in double (brute_force_area_occluders),
//   within the rounding of the float sums and corners (area_case);
// - the grid (pnGridRegionMip) at 1, 4 and 16 cells, sampled (leaf side 16,
//   4) and ramp leaves: equal to the CPU's grid with the same decisions and
//   samples; at 16 cells on regions of side <= 16 (texels) equal to brute force;
// - the node budget on the fine checkerboard at the receiver depth: within
//   budget + 3·levels + 1 nodes, equal to the recursion with that budget,
//   its error against brute force in the case name.
#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <string>
#include <tuple>

#include "check/module_check.h"
#include "check/pcss_compare.h"
#include "modules/fast_pcss_face.h"
#include "core/format.h"
#include "core/seeded_random.h"
#include "fixture_images/texture_fixture.h"
#include "pass_runners/traversal_pass.h"
#include "reference/depth_pyramid_reference.h"
#include "reference/traversal_reference.h"

namespace pn {
namespace {

constexpr int kMapSize = 300;

struct Scene {
  Image map;    // as generated
  Image depth;  // sanitized
  DepthPyramid pyramid;
  MinMaxMipChain mip;
  SummedAreaTable depth_sums;
  float largest = FLT_MIN;  // max finite |depth|
};

// Receivers relative to the region's depth range: below it, at its min, in the middle, at its max, above it.
std::vector<float> receivers_for(const Image& depth, const Rect& r) {
  float lo = INFINITY, hi = -INFINITY, finite_hi = -INFINITY;
  for (int y = r.y; y < r.y + r.height; ++y)
    for (int x = r.x; x < r.x + r.width; ++x) {
      const float d = depth.at(x, y);
      lo = std::min(lo, d), hi = std::max(hi, d);
      if (std::isfinite(d)) finite_hi = std::max(finite_hi, d);
    }
  const float top = std::isfinite(finite_hi) ? finite_hi : 1.0f;
  return {lo - 0.05f, lo, 0.5f * (lo + top), hi, top + 0.05f};
}

// Compares GPU results with expected ones: (occluders, nodes, fetches) exactly
// when `compare_counters`, occluders alone otherwise; the module's blocker mean
// (pnTraversalBlockerMean) within (terms + 2 levels + 4) ulps of the largest
// depth, terms = nodes + fetches of the reference; its occluded fraction
// (pnTraversalOccludedFraction) within the counts' bound over the smallest
// region plus 4 ulps (GLSL's division is not correctly rounded).
void add_comparison(std::vector<CaseResult>& results, const std::string& name, const Scene& scene,
                    const std::vector<TraversalResult>& expected, const std::vector<TraversalReadback>& observed,
                    const std::vector<TraversalResult>& decisions, bool compare_counters,
                    bool compare_means = true, bool fractional_counts = false) {
  const int n = static_cast<int>(expected.size());
  Image e_counts(n, 1, 3), o_counts(n, 1, 3), e_mean(n, 1), o_mean(n, 1), e_fraction(n, 1), o_fraction(n, 1);
  double terms = 0;
  for (int k = 0; k < n; ++k) {
    const TraversalResult& e = expected[static_cast<size_t>(k)];
    const TraversalReadback& o = observed[static_cast<size_t>(k)];
    const TraversalResult& d = decisions[static_cast<size_t>(k)];
    e_counts.at(k, 0, 0) = static_cast<float>(e.occluders), o_counts.at(k, 0, 0) = static_cast<float>(o.occluders);
    if (compare_counters) {
      e_counts.at(k, 0, 1) = static_cast<float>(e.nodes), o_counts.at(k, 0, 1) = static_cast<float>(o.nodes);
      e_counts.at(k, 0, 2) = static_cast<float>(e.fetches), o_counts.at(k, 0, 2) = static_cast<float>(o.fetches);
    }
    e_mean.at(k, 0) = static_cast<float>(e.blocker_mean()), o_mean.at(k, 0) = static_cast<float>(o.called_blocker_mean);
    e_fraction.at(k, 0) = static_cast<float>(e.occluded_fraction());
    o_fraction.at(k, 0) = static_cast<float>(o.called_occluded_fraction);
    terms = std::max(terms, static_cast<double>(d.nodes + d.fetches));
  }
  // Ramp leaves add non-dyadic fractions: the float sum of `terms` of them, each at most a region's
  // texels, within (terms + 4) ulps of the largest region (nodes and fetches stay integers far apart).
  double largest_region = 1.0, smallest_region = INFINITY;
  for (const TraversalResult& e : expected) {
    largest_region = std::max(largest_region, e.texels);
    if (e.texels > 0) smallest_region = std::min(smallest_region, e.texels);
  }
  const double count_bound = fractional_counts ? (terms + 4.0) * FLT_EPSILON * largest_region : 0.0;
  const Tolerance counts = fractional_counts ? Tolerance::absolute(count_bound) : Tolerance::exact();
  const std::string what = compare_counters ? " occluders, nodes, fetches" : " occluders";
  results.push_back({name + what + " (query k at (k, 0))", counts, compare(e_counts, o_counts, counts)});
  const Tolerance mean_tol =
      Tolerance::absolute((terms + 2.0 * scene.pyramid.levels + 4.0) * FLT_EPSILON * scene.largest);
  if (compare_means) results.push_back({name + " blocker mean", mean_tol, compare(e_mean, o_mean, mean_tol)});
  const Tolerance fraction_tol =
      Tolerance::absolute((std::isfinite(smallest_region) ? count_bound / smallest_region : 0.0) + 4.0 * FLT_EPSILON);
  results.push_back({name + " occluded fraction", fraction_tol, compare(e_fraction, o_fraction, fraction_tol)});
}

// Leaf side 1 over area-weighted squares (issue 51): the mip chain's walk with the table's sums, or the
// pyramid's with its means, against brute_force_area_occluders, each element within the rounding of its
// float sums ((terms + 4) ulps, terms = the GPU's nodes + fetches, and on the pyramid 2 a level its means
// were averaged over) and of the square's corners in float (4 ulps of the centre's and the side's
// magnitude on each edge texel's weight). [0] occluded area, [1] depth-weighted, [2] area, [3] the
// module's occluded fraction, [4] its blocker mean (where the occluded area is above its bound).
template <class Observe>
CaseResult area_case(const Observe& observe, const Scene& scene, const std::string& label, bool mip) {
  constexpr double u = 0x1p-24;
  std::vector<std::array<float, 3>> squares{{150.0f, 150.0f, 7.0f},  {150.5f, 150.5f, 7.0f}, {0.25f, 0.75f, 3.5f},
                                            {kMapSize - 0.3f, 4.2f, 9.9f}, {-1.25f, 40.0f, 3.0f},
                                            {150.3f, 150.6f, 1.0f},  {150.0f, 150.0f, 0.25f}, {-0.35f, 200.5f, 1.0f},
                                            {150.0f, 150.0f, kMapSize * 1.5f},
                                            {0.0f, 150.5f, 1.0f}};  // half a texel inside the map: area 0.5
  SeededRandom random(0x5eed0051u);
  for (float side : {1.5f, 2.7f, 5.25f, 16.4f, 33.9f, 100.6f})
    for (int k = 0; k < 6; ++k)
      squares.push_back({random.uniform_float(-5.0f, kMapSize + 5.0f), random.uniform_float(-5.0f, kMapSize + 5.0f),
                         side + random.uniform_float(0.0f, 0.1f)});
  std::vector<TraversalQuery> queries;
  std::vector<TraversalResult> expected;
  std::vector<double> position_error;
  for (const auto& [x, y, side] : squares) {
    const double half = 0.5 * std::clamp<double>(side, 1.0, 4.0 * kMapSize);
    const auto bound = [](double v) { return std::clamp(v, 0.0, static_cast<double>(kMapSize)); };
    const int x0 = static_cast<int>(std::floor(bound(x - half))), y0 = static_cast<int>(std::floor(bound(y - half)));
    const Rect cover{x0, y0, std::max(1, static_cast<int>(std::ceil(bound(x + half))) - x0),
                     std::max(1, static_cast<int>(std::ceil(bound(y + half))) - y0)};
    for (float receiver : receivers_for(scene.depth, Rect{std::min(cover.x, kMapSize - 1), std::min(cover.y, kMapSize - 1),
                                                          std::min(cover.width, kMapSize - std::min(cover.x, kMapSize - 1)),
                                                          std::min(cover.height, kMapSize - std::min(cover.y, kMapSize - 1))})) {
      if (!std::isfinite(receiver)) continue;
      const TraversalResult e = brute_force_area_occluders(scene.depth, x, y, side, receiver, 0.0f);
      if (!std::isfinite(e.depth_sum)) continue;  // a -Inf texel occludes with a -Inf sum: nothing to bound
      TraversalQuery q{{}, receiver, static_cast<int>(queries.size()), 0};
      q.area_x = x, q.area_y = y, q.area_side = side;
      queries.push_back(q);
      expected.push_back(e);
      position_error.push_back(area_corner_error(x, y, side, kMapSize));
    }
  }
  TraversalSettings settings;  // leaf side 1, the table's sums
  settings.area_regions = true;
  const std::vector<TraversalReadback> observed = observe(queries, settings);
  BoundedElements b;
  const double means = mip ? 0.0 : 2.0 * scene.pyramid.levels * u;  // a pyramid node's mean, averaged level by level
  for (size_t k = 0; k < queries.size(); ++k) {
    const TraversalResult& e = expected[k];
    const TraversalReadback& o = observed[k];
    const int at = static_cast<int>(k);
    const double rounding = static_cast<double>(o.nodes + o.fetches + 4) * 2.0 * u;
    const double occluded_bound = rounding * e.occluders + position_error[k];
    const double sum_bound = (rounding + means) * e.occluders * scene.largest + position_error[k] * scene.largest;
    const double area_bound = 4.0 * u * e.texels + position_error[k];
    b.add(e.occluders, o.occluders, occluded_bound, at, 0, 0);
    b.add(e.depth_sum, o.depth_sum, sum_bound, at, 0, 1);
    b.add(e.texels, o.texels, area_bound, at, 0, 2);
    const double fraction = e.occluded_fraction();
    b.add(fraction, o.called_occluded_fraction,
          e.texels > area_bound ? (occluded_bound + fraction * area_bound) / (e.texels - area_bound) + 4.0 * u : 1.0,
          at, 0, 3);
    if (e.occluders > occluded_bound) {
      const double mean = e.blocker_mean();
      b.add(mean, o.called_blocker_mean,
            (sum_bound + std::fabs(mean) * occluded_bound) / (e.occluders - occluded_bound) + 4.0 * u * std::fabs(mean),
            at, 0, 4);
    }
  }
  Tolerance tolerance;
  const Comparison c = compare_bounded(b, tolerance);
  return {label + (mip ? " mip chain leaf 1 over area-weighted squares (pnRegionArea, pnTraverseAreaMipPlane)"
                      : " pyramid leaf 1 over area-weighted squares (pnRegionArea, pnTraverseAreaPlane)") +
              " vs every texel's overlap in double (" + std::to_string(queries.size()) + " queries at (k, 0)): [0] occluded area, "
                  "[1] depth-weighted, [2] area, [3] occluded fraction, [4] blocker mean",
          tolerance, c};
}

}  // namespace

std::vector<CaseResult> run_traversal_check(const CheckEnvironment& env) {
  const DepthPyramidBuilder builder(env.device, env.tree);
  const MinMaxMipBuilder mip_builder(env.device, env.tree);
  const SummedAreaPass depth_sums_pass(env.device, env.tree);
  const TraversalPass pass(env.device, env.tree);
  const SampleTable table = generate_sample_table(kSampleTableSeed);
  const std::unique_ptr<DeviceTexture> table_texture = upload_sample_table(env.device, table);
  std::vector<CaseResult> results;

  // Both structures: the decreased pyramid (pnTraverseRegion) and the aligned mip chain (pnTraverseRegionMip).
  struct Structure {
    const char* label;
    bool mip;
  };
  const Structure structures[] = {{"", false}, {" mip chain", true}};
  // The GPU's results over a structure, and the CPU recursion's decisions over the same one.
  const auto observe = [&](const Structure& st, const Scene& scene, const std::vector<TraversalQuery>& queries,
                           const TraversalSettings& s) {
    const TraversalBatch batch(env.device, queries, s.area_regions);
    pass.dispatch(st.mip ? TraversalStructure{nullptr, &scene.mip, &scene.depth_sums} : TraversalStructure{&scene.pyramid},
                  *table_texture, batch, s);
    return batch.read();
  };
  const auto recursion = [&](const Structure& st, const Scene& scene, const std::vector<TraversalQuery>& queries,
                             const TraversalSettings& s) {
    std::vector<TraversalResult> out;
    for (const TraversalQuery& q : queries) {
      const TraversalParams p{q.receiver_depth, s.bias, s.leaf_side, s.leaf_mode, s.node_budget, q.pixel_x, q.pixel_y};
      out.push_back(st.mip ? aligned_traversal_reference(scene.depth, table, q.region, p, s.depth_sums)
                           : traversal_reference(scene.depth, scene.pyramid.levels - 1, table, q.region, p));
    }
    return out;
  };

  SeededRandom random(0x5eed0006u);
  for (const auto& fixture : check_texture_fixtures(env)) {
    Scene scene;
    scene.map = generate_fixture(fixture, kMapSize, kMapSize);
    scene.depth = sanitized_depths(scene.map);
    const std::unique_ptr<DeviceTexture> map_texture = env.device.upload(scene.map);
    scene.pyramid = builder.build(*map_texture, kMapSize, kMapSize, 31);
    scene.mip = mip_builder.build(*map_texture, kMapSize);
    scene.depth_sums = depth_sums_pass.build(*map_texture, kMapSize, kMapSize);
    scene.largest = largest_finite_magnitude(scene.depth, FLT_MIN);
    // Exact: leaf side 1, power-of-two windows and exact regions, against brute force.
    std::vector<Rect> regions;
    for (int side = 1; side <= 256; side *= 2) {
      regions.push_back({kMapSize - side, (side * 7) % (kMapSize - side + 1), side, side});
      if (side <= 64) regions.push_back({0, 0, side, side});  // and at the corner (large ones cost llvmpipe seconds)
    }
    for (int side = 3; side <= 64; side += 2) regions.push_back({17, 5, side, side});
    for (Rect r : {Rect{1, 2, 100, 37}, Rect{30, 40, 255, 129}, Rect{99, 0, 200, 200}, Rect{0, 299, 300, 1}})
      regions.push_back(r);
    std::vector<TraversalQuery> queries;
    for (const Rect& r : regions)
      for (float receiver : receivers_for(scene.depth, r))
        queries.push_back({r, receiver, static_cast<int>(queries.size()), 3 * static_cast<int>(queries.size())});
    TraversalSettings exact_settings;
    std::vector<TraversalResult> brute;
    for (const TraversalQuery& q : queries) brute.push_back(brute_force_occluders(scene.depth, q.region, q.receiver_depth, 0.0f));
    const std::string label = std::string(fixture.name) + " " + std::to_string(kMapSize) + "x" + std::to_string(kMapSize);
    for (const Structure& st : structures) {
      const auto observed = observe(st, scene, queries, exact_settings);
      const auto decisions = recursion(st, scene, queries, exact_settings);
      add_comparison(results, label + st.label + " leaf 1 vs brute force:", scene, brute, observed, decisions, false);
      add_comparison(results, label + st.label + " leaf 1 vs recursion:", scene, decisions, observed, decisions, true);
    }

    // Leaf side 1 over area-weighted squares (pnRegionArea; issue 51) on both structures (the mip chain
    // with the table's sums), against every texel's overlap in double.
    for (const Structure& st : structures)
      results.push_back(area_case(
          [&](const std::vector<TraversalQuery>& q, const TraversalSettings& s) { return observe(st, scene, q, s); },
          scene, label, st.mip));

    // Leaf side 1 with a receiver plane over both structures against the plane's brute force: a node is
    // decided against the plane's range over it, widened by rounding, so the counts are exact but for
    // texels within rounding of their own threshold.
    {
      std::vector<TraversalQuery> plane_queries;
      // (0.5, 0.5): steep, and a gradient with both components equal, as a flat test's (0, 0) has.
      const float gradients[][2] = {{0.004f, -0.003f}, {-0.03f, 0.02f}, {0.2f, -0.1f}, {0.5f, 0.5f}};
      for (size_t i = 0; i < regions.size(); i += 2) {
        const Rect& r = regions[i];
        const std::vector<float> rs = receivers_for(scene.depth, r);
        for (size_t g = 0; g < std::size(gradients); ++g)
          for (size_t k = 1; k < 4; ++k) {  // at the region's min, middle and max: the plane crosses its depths
            if (!std::isfinite(rs[k])) continue;  // a -Inf min: every texel's threshold is -Inf
            TraversalQuery q{r, rs[k], static_cast<int>(plane_queries.size()), 0};
            // The plane's point inside the region, or 40 texels beyond its corner (extrapolated).
            const float off = (k == 2) ? -40.0f : 0.37f;
            q.receiver_u = static_cast<float>(r.x) + 0.5f * static_cast<float>(r.width) + off;
            q.receiver_v = static_cast<float>(r.y) + 0.5f * static_cast<float>(r.height) - 0.61f;
            q.gradient_u = gradients[g][0], q.gradient_v = gradients[g][1];
            plane_queries.push_back(q);
          }
      }
      TraversalSettings s;
      s.bias = 0.001f;
      for (const Structure& st : structures) {
      const auto observed = observe(st, scene, plane_queries, s);
      BoundedElements occluders, sums;
      double open = 0.0, texels = 0.0;
      for (size_t k = 0; k < plane_queries.size(); ++k) {
        const TraversalQuery& q = plane_queries[k];
        const PlaneOccluders b = brute_force_occluders_plane(scene.depth, q.region, q.receiver_u, q.receiver_v,
                                                             q.receiver_depth, q.gradient_u, q.gradient_v, s.bias,
                                                             std::ldexp(1.0, -20));
        const TraversalResult& o = observed[k];
        const int x = static_cast<int>(k);
        occluders.add_interval(b.certain.occluders, b.certain.occluders + b.open, static_cast<float>(o.occluders), x, 0);
        // The GPU's float sum of its nodes' and texels' sums: within (nodes + fetches + 8) ulps of the largest depth
        // times the texels summed.
        const double rounding = static_cast<double>(o.nodes + o.fetches + 8) * FLT_EPSILON * scene.largest *
                                (b.certain.occluders + b.open + 1.0);
        sums.add_interval(b.certain.depth_sum + b.open_depth_lo - rounding,
                          b.certain.depth_sum + b.open_depth_hi + rounding, static_cast<float>(o.depth_sum), x, 0);
        open += b.open, texels += b.certain.texels;
      }
      const std::string name = label + st.label + " leaf 1 with a receiver plane vs its brute force (" +
                               std::to_string(plane_queries.size()) + " queries, query k at (k, 0)): ";
      for (const auto& [what, elements] : {std::pair<const char*, const BoundedElements*>{"occluders", &occluders},
                                           {"depth sum", &sums}}) {
        Tolerance tolerance = Tolerance::absolute(0.0);
        const Comparison c = compare_bounded(*elements, tolerance);
        results.push_back({name + what + " within the rounding interval", tolerance, c});
      }
      BoundedElements open_share;
      open_share.add(0.0, static_cast<float>(texels > 0 ? open / texels : 0.0), 0.01, 0, 0);
      Tolerance open_tolerance = Tolerance::absolute(0.0);
      const Comparison open_result = compare_bounded(open_share, open_tolerance);
      results.push_back({name + "texels left open by rounding " + format_number("%.0f", open) + " of " +
                             format_number("%.0f", texels) + " (<= 1 %)",
                         open_tolerance, open_result});
      }
    }

    // Sampled and min leaves against the recursion with the same table and decisions.
    std::vector<TraversalQuery> leaf_queries;
    for (int k = 0; k < 96; ++k) {
      const int side = 1 << random.uniform_int(4, 8);
      const Rect r{random.uniform_int(0, kMapSize - side), random.uniform_int(0, kMapSize - side), side, side};
      const std::vector<float> rs = receivers_for(scene.depth, r);
      leaf_queries.push_back({r, random.uniform_float(rs[0], rs[4]), random.uniform_int(0, 1023), random.uniform_int(0, 1023)});
    }
    for (const Structure& st : structures)
      for (LeafMode mode : {LeafMode::sampled, LeafMode::quad, LeafMode::min, LeafMode::ramp})
        for (int leaf : {2, 4, 8, 16}) {
          if (mode == LeafMode::quad && leaf < 8) continue;  // quad leaves of side <= 4 are sampled ones
          TraversalSettings s;
          s.leaf_side = leaf, s.leaf_mode = mode, s.bias = 0.001f;
          // The mip chain's other depth sums: none (Step 5) and midpoint (no table).
          s.depth_sums = leaf == 4 ? DepthSums::none : leaf == 16 ? DepthSums::midpoint : DepthSums::table;
          const auto expected = recursion(st, scene, leaf_queries, s);
          const auto observed = observe(st, scene, leaf_queries, s);
          add_comparison(results,
                         label + st.label +
                             (mode == LeafMode::sampled ? " sampled"
                              : mode == LeafMode::quad  ? " quad (4 samples)"
                              : mode == LeafMode::min   ? " min (HQEPCSS)"
                                                        : " ramp") +
                             " leaves, side " + std::to_string(leaf) + ":",
                         scene, expected, observed, expected, true, s.depth_sums != DepthSums::none,
                         mode == LeafMode::ramp);
        }

    // Fast PCSS's leaf side for a region (pnTraversalRegionLeafSide): leaf side 16 over regions of side
    // 16…256, the leaf at most a quarter of the region's side (a power of two), 1 under 4: the
    // recursion with that side (4 at side 16, 8 at 32, 16 from 64 on). And with Fast PCSS's work
    // budget (issue 52, fast_pcss.h): leaves of at least the region's side / its divisor, of 4 samples
    // each — from leaf side 4, so that the divisor binds on these regions of side 16…256.
    for (const Structure& st : structures)
      for (const auto& [leaf, divisor, mode] : {std::tuple{16, 0, LeafMode::sampled},
                                                std::tuple{4, kFastPcssLeafDivisor, kFastPcssLeafMode}}) {
        if (!st.mip) continue;
        TraversalSettings s;
        s.leaf_side = leaf, s.region_leaf = true, s.leaf_divisor = divisor, s.leaf_mode = mode, s.bias = 0.001f;
        std::vector<TraversalResult> expected;
        for (const TraversalQuery& q : leaf_queries) {
          TraversalSettings own = s;
          const int longer = std::max(q.region.width, q.region.height);
          int quarter = 1;
          while (quarter * 2 <= longer / 4) quarter *= 2;
          own.leaf_side = std::min(std::max(s.leaf_side, divisor > 0 ? longer / divisor : 0), quarter);
          if (own.leaf_side < 4) own.leaf_side = 1;
          expected.push_back(recursion(st, scene, {q}, own)[0]);
        }
        const auto observed = observe(st, scene, leaf_queries, s);
        add_comparison(results,
                       label + st.label +
                           (divisor > 0 ? " Fast PCSS's quad leaves (issue 52): side max(4, the region's side / " +
                                              std::to_string(divisor) + "), 4 samples"
                                        : " sampled leaves of side 16") +
                           ", at most a quarter of the region's side:",
                       scene, expected, observed, expected, true, true, false);
      }

    // The leaf side from the region (pnTraversalLeafSide's divisor, Fast PCSS's `leafDivisor`): the
    // recursion with the side the definition gives, max(leaf, the region's longer side / divisor);
    // on the ramp and the noise (the suite's time: the other fixtures add nothing here).
    const bool divided = std::string(fixture.name) == "ramp" || std::string(fixture.name) == "noise";
    for (const Structure& st : structures)
      for (int divisor : divided ? std::vector<int>{1, 4} : std::vector<int>{}) {
        TraversalSettings s;
        s.leaf_side = 2, s.leaf_divisor = divisor, s.bias = 0.001f;
        std::vector<TraversalResult> expected;
        for (const TraversalQuery& q : leaf_queries) {
          TraversalSettings own = s;
          own.leaf_side = std::max(s.leaf_side, std::max(q.region.width, q.region.height) / divisor);
          expected.push_back(recursion(st, scene, {q}, own)[0]);
        }
        const auto observed = observe(st, scene, leaf_queries, s);
        add_comparison(results,
                       label + st.label + " sampled leaves of side max(2, the region's side / " +
                           std::to_string(divisor) + "):",
                       scene, expected, observed, expected, true, true, false);
      }

    // Regions of unequal sides along the map's edges, as Fast PCSS's square regions are where the map
    // clips them (issue 54 M03: a grid cell taken from the shorter side passed every check).
    std::vector<TraversalQuery> grid_queries = leaf_queries;
    for (int k = 0; k < 32; ++k) {
      const int wide = random.uniform_int(40, kMapSize / 2), narrow = random.uniform_int(3, 24);
      const bool across = k % 2 == 0;  // wide along x, clipped in y; or the other way round
      const int w = across ? wide : narrow, h = across ? narrow : wide;
      const Rect r{k % 4 < 2 ? random.uniform_int(0, kMapSize - w) : kMapSize - w,
                   k % 4 < 2 ? kMapSize - h : random.uniform_int(0, kMapSize - h), w, h};
      const std::vector<float> rs = receivers_for(scene.depth, r);
      grid_queries.push_back({r, random.uniform_float(rs[0], rs[4]), random.uniform_int(0, 1023), random.uniform_int(0, 1023)});
    }
    // The grid (pnGridRegionMip) over the mip chain: against the CPU's grid with the same decisions and
    // samples, and with grid >= the region's side (texels) against brute force.
    for (int grid : {1, 4, 16})
      for (const auto& [mode, leaf] : {std::pair{LeafMode::sampled, 16}, {LeafMode::sampled, 4}, {LeafMode::ramp, 16}}) {
        TraversalSettings s;
        s.grid = grid, s.leaf_side = leaf, s.leaf_mode = mode, s.bias = 0.001f;
        s.depth_sums = grid == 4 ? DepthSums::none : grid == 16 ? DepthSums::midpoint : DepthSums::table;
        std::vector<TraversalResult> expected;
        for (const TraversalQuery& q : grid_queries) {
          const TraversalParams p{q.receiver_depth, s.bias, s.leaf_side, s.leaf_mode, s.node_budget, q.pixel_x, q.pixel_y};
          expected.push_back(aligned_grid_reference(scene.depth, table, q.region, p, s.depth_sums, grid));
        }
        const auto observed = observe(structures[1], scene, grid_queries, s);
        add_comparison(results,
                       label + " grid " + std::to_string(grid) + (mode == LeafMode::ramp ? ", ramp" : ", sampled") +
                           " leaves of side <= " + std::to_string(leaf) + " (square and edge-clipped regions):",
                       scene, expected, observed, expected, true, s.depth_sums != DepthSums::none, mode == LeafMode::ramp);
      }
    {
      std::vector<TraversalQuery> small;
      std::vector<TraversalResult> brute_small;
      for (size_t k = 0; k < queries.size(); ++k)
        if (std::max(queries[k].region.width, queries[k].region.height) <= 16)
          small.push_back(queries[k]), brute_small.push_back(brute[k]);
      TraversalSettings s;
      s.grid = 16;
      const auto observed = observe(structures[1], scene, small, s);
      add_comparison(results, label + " grid 16 on regions of side <= 16 (texels) vs brute force:", scene, brute_small,
                     observed, brute_small, false);
    }

    if (std::string(fixture.name) == "fine_checker") {
      // The pathological case: every node ambiguous at receiver 0.5.
      for (const Structure& st : structures)
        for (int budget : {8, 64, 1000}) {
          TraversalSettings s;
          s.node_budget = budget;
          const std::vector<TraversalQuery> q{{{0, 0, 256, 256}, 0.5f, 0, 0}, {{10, 20, 200, 150}, 0.5f, 5, 1}};
          const auto expected = recursion(st, scene, q, s);
          const auto observed = observe(st, scene, q, s);
          double worst = 0.0;
          long most_nodes = 0;
          for (size_t k = 0; k < q.size(); ++k) {
            const auto b = brute_force_occluders(scene.depth, q[k].region, 0.5f, 0.0f);
            worst = std::max(worst, std::fabs(observed[k].occluded_fraction() - b.occluded_fraction()));
            most_nodes = std::max(most_nodes, observed[k].nodes);
          }
          // Levels: 8 for the pyramid's 256² root; the mip chain's virtual root is one above, and a
          // step may add four texels.
          const long bound = budget + 3 * (st.mip ? 9 : 8) + (st.mip ? 4 + 4 : 1);
          const std::string name = label + st.label + " budget " + std::to_string(budget);
          add_comparison(results,
                         name + " (nodes " + std::to_string(most_nodes) + " <= " + std::to_string(bound) +
                             "; fraction error vs brute force " + format_number("%.3f", worst) + "):",
                         scene, expected, observed, expected, true);
          Image within(1, 1, 1, 1.0f), observed_within(1, 1, 1, most_nodes <= bound ? 1.0f : 0.0f);
          results.push_back({name + ": nodes within the budget's bound", Tolerance::exact(),
                             compare(within, observed_within, Tolerance::exact())});
        }
    }
  }
  return results;
}

}  // namespace pn
