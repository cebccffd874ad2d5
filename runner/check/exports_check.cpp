// Cases of the exports check (issues 27, 39): every technique's public call as an engine makes it
// — the export entries glsl/exports/X.comp (what `penumbra bundle X.glsl --target hlsl|msl`
// translates) and X.frag (the same call in a fragment shader, a full-screen triangle) — in both
// stages, on the executor under check (on `--api hlsl`, the HLSL export itself, compiled back),
// against the CPU's definitions of the calls, for the pixels of each scene that see a surface:
// - pnExactPcss against exact PCSS brute force (exact_pcss_reference, double);
// - pnPcf against 2×2 bilinear PCF (pcf_plane_reference, double);
// - pnHqepcss with its exact settings (no refinement, exact regions, leaf 1) over the decreased
//   depth pyramid built on the executor, against exact PCSS brute force, and with PN_AREA_EDGES
//   against the squares' definition with area-weighted edges (exact_pcss_area_reference);
// - pnFastPcss with its exact settings (no refinement, exact regions, leaf 1) against exact PCSS
//   brute force, over the min/max mip chain built on the same executor: with the summed-area
//   table's blocker sums (exports/fast_pcss with PN_EXPORT_SUM_TABLE) and, as an engine includes
//   it (no define), with the chain's midpoint sums on a map whose occluding nodes are flat — and
//   so again without PN_FAST_PCSS_ABLATIONS (the export as bundled: the shipped walk alone, leaf 1
//   descending to the texels); with its shipped settings, the shipped walk of that build equal,
//   bit for bit, to traversal_mip.glsl's general walk (the same settings but a node budget of
//   2^26 - 1, never reached: not the shipped ones, so the ablations' build walks them);
// - pnPoissonPcss and pnVogelPcss, with their defaults (pnXDefaults) and with other counts and
//   scale, rotated, against the disks' PCSS on the CPU (disk_pcss_reference: open samples make
//   the visibility an interval; a receiver whose blocker search float could decide otherwise is
//   left out and counted);
// - pnBackprojection, every texel resolved, against the rays through the map's surface
//   (backprojection_reference: an interval), and its overload with a second layer against the
//   rays through the slabs (backprojection_slab_reference);
// each through both overloads where it has two (half the receivers through the receiverPlane one:
// with a zero plane for the square-region calls — their planes are the fast_pcss check's — and a
// small plane of its own for the disks), the pixels within rounding of a decision left out and
// counted. The shadow map and G-buffer are the CPU's ray casts (the shadow_map check holds the
// GPU's rasterised ones to them), so the check needs nothing but the executor.
#include <cmath>
#include <string>
#include <vector>

#include "backprojection.h"
#include "check/disk_layouts.h"
#include "check/module_check.h"
#include "check/pcss_compare.h"
#include "check/vsm_tolerance.h"
#include "core/format.h"
#include "core/seeded_random.h"
#include "fast_pcss.h"
#include "fixture_images/texture_fixture.h"
#include "gl/std140.h"
#include "hqepcss.h"
#include "modules/vogel_pcss_face.h"
#include "pass_runners/depth_pyramid_pass.h"
#include "pass_runners/export_pass.h"
#include "pass_runners/minmax_mip_pass.h"
#include "pass_runners/shade_pass.h"
#include "pass_runners/summed_area_pass.h"
#include "pass_runners/traversal_pass.h"
#include "pass_runners/vsm_pass.h"
#include "pipeline/pcss_settings.h"
#include "reference/backprojection_reference.h"
#include "reference/disk_pcss_reference.h"
#include "reference/pcss_reference.h"
#include "reference/vogel_pcss_reference.h"
#include "reference/vsm_reference.h"
#include "sampling/poisson_disk.h"
#include "sampling/sample_table_generator.h"
#include "scene/light_block.h"
#include "scene/scene.h"
#include "scenes.h"

namespace pn::glsl {
#include "exports/exact_pcss_export.h"
#include "exports/fast_pcss_export.h"
#include "exports/hqepcss_export.h"
#include "exports/pcf_export.h"
#include "exports/poisson_pcss_export.h"
#include "exports/vogel_pcss_export.h"
#include "exports/backprojection_export.h"
#include "exports/vsm_export.h"
PN_STD140_OFFSET(PnPoissonPcssExport, rotationSin, 44);
PN_STD140_OFFSET(PnPoissonPcssExport, rotationFromAngle, 52);
PN_STD140_OFFSET(PnVogelPcssExport, filterSamples, 36);
PN_STD140_OFFSET(PnBackprojectionExport, thickness, 44);
PN_STD140_OFFSET(PnBackprojectionExport, slabs, 48);
PN_STD140_OFFSET(PnVsmExport, kind, 36);
PN_STD140_SIZE(PnExactPcssExport, 32);
PN_STD140_OFFSET(PnExactPcssExport, bias, 24);
PN_STD140_SIZE(PnFastPcssExport, 80);
PN_STD140_OFFSET(PnFastPcssExport, grid, 64);
PN_STD140_SIZE(PnHqepcssExport, 64);
PN_STD140_OFFSET(PnHqepcssExport, nodeBudget, 48);
}  // namespace pn::glsl

namespace pn {
namespace {

constexpr int kMap = 64, kScreen = 48;  // brute force on the CPU stays fast
constexpr double kRotation = 0.7;       // the Poisson disks' rotation, radians

struct SceneImages {
  Image map, gbuffer;
  std::vector<ExportReceiver> receivers;  // every pixel that sees a surface, in row order
  std::vector<std::pair<int, int>> pixels;
};

SceneImages ray_cast(const Scene& scene) {
  SceneImages out{Image(kMap, kMap), Image(kScreen, kScreen, 4), {}, {}};
  for (int y = 0; y < kMap; ++y)
    for (int x = 0; x < kMap; ++x) out.map.at(x, y) = ray_cast_light_depth(scene, x, y);
  for (int y = 0; y < kScreen; ++y)
    for (int x = 0; x < kScreen; ++x) {
      const Receiver r = ray_cast_receiver(scene, x, y, kScreen);
      if (!r.valid) continue;
      const float v[4] = {float(r.u), float(r.v), float(r.depth), 1.0f};
      for (int c = 0; c < 4; ++c) out.gbuffer.at(x, y, c) = v[c];
      // The G-buffer's floats, as the reference reads them; every other receiver through the plane overload.
      out.receivers.push_back({v[0], v[1], v[2], out.receivers.size() % 2 == 1, 0.0f, 0.0f});
      out.pixels.push_back({x, y});
    }
  return out;
}

// The receivers' visibilities against the reference's on the screen (pixels without a surface
// are not receivers: they keep the reference's value).
CaseResult against(const std::string& name, const SceneImages& s, const PcssReference& reference,
                   const std::vector<float>& observed, Tolerance tolerance = Tolerance::absolute(kFractionRounding)) {
  Image seen = reference.visibility;
  for (std::size_t k = 0; k < observed.size(); ++k) seen.at(s.pixels[k].first, s.pixels[k].second) = observed[k];
  const int ambiguous = leave_out_ambiguous(reference, seen);
  return {name + " (" + std::to_string(observed.size()) + " receivers, both overloads; " + std::to_string(ambiguous) +
              " pixels within rounding of a decision left out)",
          tolerance, compare(reference.visibility, seen, tolerance)};
}

// The settings pnFastPcss and pnHqepcss share, as they make the call exact PCSS (fast_pcss.glsl
// "Exactness"; the fast_pcss check's "hqepcss, refine 0, leaf 1, exact regions"): no refinement,
// exact regions, leaf 1, no budget; filter scale c.
template <class Block>
Block exact_settings_block(const LightModel& light, float bias, float c) {
  Block b{};
  set_light_fields(b, light);
  b.bias = bias;
  b.filterScale = c;
  b.refineIterations = 0;
  b.regionMode = PN_REGION_EXACT;
  b.leafSide = 1;
  b.leafDivisor = 0;
  b.nodeBudget = PN_TRAVERSAL_NO_BUDGET;
  return b;
}

// pnFastPcss's besides: the summed-area table's exact blocker sums, no grid.
glsl::PnFastPcssExport exact_fast_block(const LightModel& light, float bias, float c, int depth_sums = PN_DEPTH_SUMS_TABLE) {
  glsl::PnFastPcssExport b = exact_settings_block<glsl::PnFastPcssExport>(light, bias, c);
  b.leafMode = PN_LEAF_SAMPLED;
  b.blockerLeafMode = PN_FAST_PCSS_SAME_LEAF_MODE;
  b.depthSums = depth_sums;
  b.grid = 0;
  return b;
}

// A map an engine's Fast PCSS (no PN_TRAVERSAL_SUM_TABLE: the chain's midpoint sums) computes
// exactly: blockers of one depth (so every node wholly below a receiver has min = max) in
// rectangles over an empty (+Inf) map, and receivers at random places and depths behind them.
SceneImages one_depth_blockers(std::uint32_t seed) {
  SceneImages out{Image(kMap, kMap, 1, INFINITY), Image(kScreen, kScreen, 4), {}, {}};
  SeededRandom random(seed);
  constexpr float kBlocker = 3.0f;
  for (int r = 0; r < 6; ++r) {
    const int x0 = random.uniform_int(0, kMap - 8), y0 = random.uniform_int(0, kMap - 8);
    const int w = random.uniform_int(3, 20), h = random.uniform_int(3, 20);
    for (int y = y0; y < std::min(kMap, y0 + h); ++y)
      for (int x = x0; x < std::min(kMap, x0 + w); ++x) out.map.at(x, y) = kBlocker;
  }
  for (int y = 0; y < kScreen; ++y)
    for (int x = 0; x < kScreen; ++x) {
      const float v[4] = {random.uniform_float(0.0f, static_cast<float>(kMap)),
                          random.uniform_float(0.0f, static_cast<float>(kMap)), random.uniform_float(3.2f, 8.0f), 1.0f};
      for (int c = 0; c < 4; ++c) out.gbuffer.at(x, y, c) = v[c];
      out.receivers.push_back({v[0], v[1], v[2], out.receivers.size() % 2 == 1, 0.0f, 0.0f});
      out.pixels.push_back({x, y});
    }
  return out;
}


// The disk receivers: those of the scene, half with a small receiver plane of their own.
std::vector<ExportReceiver> disk_receivers(const SceneImages& s) {
  std::vector<ExportReceiver> out = s.receivers;
  for (std::size_t k = 0; k < out.size(); ++k)
    if (out[k].plane) out[k].du = 2e-4f * static_cast<float>(int(k % 5) - 2), out[k].dv = 1e-4f * static_cast<float>(int(k % 3) - 1);
  return out;
}

// The GPU's visibilities inside the CPU's intervals; receivers the reference leaves open are left out.
CaseResult interval_case(const std::string& name, const std::vector<DiskPcssResult>& expected,
                         const std::vector<float>& observed) {
  BoundedElements elements;
  int left_out = 0, shadowed = 0;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    if (expected[k].ambiguous) {
      ++left_out;
      continue;
    }
    shadowed += expected[k].visibility_lo < 1.0 ? 1 : 0;
    const auto [x, y] = ExportPass::texel(k, expected.size());
    // The interval, widened by the float rounding of 1 - occluders / samples.
    const double lo = expected[k].visibility_lo, hi = expected[k].visibility_hi;
    elements.add(0.5 * (lo + hi), observed[k], 0.5 * (hi - lo) + kFractionRounding, x, y);
  }
  Tolerance tolerance = Tolerance::absolute(kFractionRounding);
  const Comparison c = compare_bounded(elements, tolerance);
  return {name + " (" + std::to_string(expected.size()) + " receivers, " + std::to_string(shadowed) +
              " shadowed, receiver k at texel (k mod s, k / s); " + std::to_string(left_out) +
              " whose blocker search float could decide otherwise left out)",
          tolerance, c};
}

const char* stage_name(ShadeStage stage) { return stage == ShadeStage::fragment ? "fragment" : "compute"; }

}  // namespace

// pnVsm, pnEvsm2 and pnEvsm4 on the two-occluder fixture: the moments built and blurred on the
// executor (the vsm check holds them to the definition) and read back, a receiver a texel at a
// random place in it and a random depth around its window's depths; each against vsm.glsl's
// definition in double on those moments (vsm_reference.h), within the vsm check's bound.
void vsm_cases(const CheckEnvironment& env, std::vector<CaseResult>& results) {
  const VsmMomentsPass moments(env.device, env.tree);
  const DepthPyramidBuilder pyramids(env.device, env.tree);
  const ExportPass pass(env.device, env.tree, "vsm");
  const Image depth = generate_two_occluders(fixtures::kTwoOccluders);
  const int n = depth.width;
  const std::unique_ptr<DeviceTexture> map = env.device.upload(depth);
  const DepthPyramid pyramid = pyramids.build(*map, n, n, 30);
  constexpr float kBias = 0.01f;
  SeededRandom random(0x5eed0e5au);
  std::vector<ExportReceiver> receivers;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const DepthRange r = window_depth_range(depth, x, y, BlurParams{}.radius);
      const float lo = std::isfinite(r.min) ? r.min : 0.5f, hi = std::isfinite(r.max) ? r.max : 0.75f;
      receivers.push_back({x + random.uniform_float(0.0f, 0.99f), y + random.uniform_float(0.0f, 0.99f),
                           random.uniform_float(lo - 0.05f, hi + 0.05f), false, 0.0f, 0.0f});
    }
  for (const VsmKind kind : {VsmKind::vsm, VsmKind::evsm2, VsmKind::evsm4}) {
    VsmParams params;
    params.kind = kind;
    params.near_depth = -0.1f, params.far_depth = 1.2f;  // the fixture's depths lie in [0, 1]
    const VsmMoments blurred = moments.blurred(moments.moments(*map, n, n, params), params);
    const Image window = channels_of(env.device.read_texture(*blurred.texture), 0, blurred.channels);
    Image expected(n, n);
    for (int k = 0; k < n * n; ++k) {
      const int x = k % n, y = k / n;
      const float t = receivers[static_cast<std::size_t>(k)].depth - kBias;  // the float t the module forms
      const double p = vsm_bound(vsm_tolerance::moments_at(window, x, y), t, params);
      const double code = depth_range_bound(window_depth_range(depth, x, y, params.blur.radius), t);
      expected.at(x, y) = static_cast<float>(vsm_visibility(code, reduce_bleeding(p, params.bleeding_reduction)));
    }
    const glsl::PnVsmExport block{params.positive_exponent, params.positive_exponent, params.negative_exponent,
                                  params.near_depth, params.far_depth, kBias, params.min_variance,
                                  params.bleeding_reduction, params.blur.radius, static_cast<int>(kind)};
    const Tolerance tolerance = Tolerance::absolute(vsm_tolerance::reduced_tolerance(params));
    for (const ShadeStage stage : {ShadeStage::compute, ShadeStage::fragment}) {
      const std::vector<float> got =
          pass.run(stage, {{PN_EXPORT_MOMENTS_BINDING, *blurred.texture}, {PN_EXPORT_VSM_PYRAMID_BINDING, *pyramid.texture}},
                   receivers, query_block(block));
      Image observed(n, n);
      for (int k = 0; k < n * n; ++k) observed.at(k % n, k / n) = got[static_cast<std::size_t>(k)];
      results.push_back({std::string(fixtures::kTwoOccluders.name) + ": " + stage_name(stage) + " exports/vsm (" +
                             (kind == VsmKind::vsm ? "pnVsm" : kind == VsmKind::evsm2 ? "pnEvsm2" : "pnEvsm4") +
                             ", a receiver a texel, at (x, y)) vs the definition in double on the executor's moments",
                         tolerance, compare(expected, observed, tolerance)});
    }
  }
}

// A call's `pnXDefaults` (the export's block asks for it with filterScale or side <= 0) against
// the same call with the documented defaults written into the block (the module's header
// constants): equal bit for bit, so the defaults function returns what the header says.
CaseResult defaults_case(const std::string& name, const std::vector<float>& from_defaults,
                         const std::vector<float>& from_header) {
  Image expected(static_cast<int>(from_header.size()), 1), observed(static_cast<int>(from_header.size()), 1);
  for (std::size_t k = 0; k < from_header.size(); ++k)
    expected.at(static_cast<int>(k), 0) = from_header[k], observed.at(static_cast<int>(k), 0) = from_defaults[k];
  return {name + " (" + std::to_string(from_header.size()) + " receivers, receiver k at (k, 0))", Tolerance::exact(),
          compare(expected, observed, Tolerance::exact())};
}

std::vector<CaseResult> run_exports_check(const CheckEnvironment& env) {
  // PN_AREA_EDGES 0: the integer squares; the modules' default (1, the squares with area-weighted
  // edges) is what the `_area` exports compile.
  const Define texel_squares{"PN_AREA_EDGES", "0"};
  const ExportPass exact(env.device, env.tree, "exact_pcss", {texel_squares});
  const ExportPass exact_area(env.device, env.tree, "exact_pcss");
  const ExportPass pcf(env.device, env.tree, "pcf");
  const ExportPass fast_table(env.device, env.tree, "fast_pcss",
                              {{"PN_EXPORT_SUM_TABLE", "1"}, {"PN_EXPORT_ABLATIONS", "1"}, texel_squares});
  const ExportPass fast(env.device, env.tree, "fast_pcss", {{"PN_EXPORT_ABLATIONS", "1"}, texel_squares});
  const ExportPass fast_shipped(env.device, env.tree, "fast_pcss", {texel_squares});
  const ExportPass fast_area(env.device, env.tree, "fast_pcss");  // the export as bundled
  const ExportPass hqepcss(env.device, env.tree, "hqepcss", {texel_squares});
  const ExportPass hqepcss_area(env.device, env.tree, "hqepcss");
  const ExportPass poisson(env.device, env.tree, "poisson_pcss");
  const ExportPass vogel(env.device, env.tree, "vogel_pcss");
  const ExportPass backprojection(env.device, env.tree, "backprojection");
  const MinMaxMipBuilder mips(env.device, env.tree);
  const DepthPyramidBuilder pyramids(env.device, env.tree);
  const SummedAreaPass sums(env.device, env.tree);
  const std::unique_ptr<DeviceTexture> table = upload_sample_table(env.device, generate_sample_table(kSampleTableSeed));
  const float bias = exact_pcss().bias;
  // The export's constant disks (exports/poisson_disks.glsl).
  const std::vector<Sample> blocker_disk = poisson_disk(PN_POISSON_BLOCKER_SAMPLES, kPoissonBlockerDiskSeed).points;
  const std::vector<Sample> filter_disk = poisson_disk(PN_POISSON_PCF_SAMPLES, kPoissonFilterDiskSeed).points;
  std::vector<CaseResult> results;
  vsm_cases(env, results);
  {
    // pnFastPcss as an engine includes it (no define: the chain's midpoint sums), on blockers of
    // one depth, where those sums are exact.
    const LightModel light = make_scene(fixtures::kScenes[0], kMap).light;
    const SceneImages s = one_depth_blockers(0x5eed0039u);
    const std::unique_ptr<DeviceTexture> map = env.device.upload(s.map);
    const MinMaxMipChain mip = mips.build(*map, kMap);
    const PcssReference reference = exact_pcss_reference(s.map, s.gbuffer, light, bias, 1.0, kPcssDecisionMargin);
    const PcssReference area_reference = exact_pcss_area_reference(s.map, s.gbuffer, light, bias, 1.0, kAreaEdgeMargin);
    const glsl::PnFastPcssExport block = exact_fast_block(light, bias, 1.0f, PN_DEPTH_SUMS_MIDPOINT);
    const std::vector<QueryTexture> textures{{PN_EXPORT_DEPTH_MAP_BINDING, *map}, {PN_EXPORT_FAST_MIP_BINDING, *mip.texture},
                                             {PN_EXPORT_SAMPLE_TABLE_BINDING, *table}};
    for (const ShadeStage stage : {ShadeStage::compute, ShadeStage::fragment}) {
      results.push_back(against(std::string("blockers of one depth, 64² map: ") + stage_name(stage) +
                                    " exports/fast_pcss as an engine includes it (pnFastPcss: refine 0, exact regions, "
                                    "leaf 1, the chain's midpoint sums) vs exact PCSS brute force on the CPU",
                                s, reference, fast.run(stage, textures, s.receivers, query_block(block))));
      results.push_back(against(std::string("blockers of one depth, 64² map: ") + stage_name(stage) +
                                    " exports/fast_pcss without PN_FAST_PCSS_ABLATIONS (the shipped walk, leaf 1 "
                                    "descending to the texels) vs exact PCSS brute force on the CPU",
                                s, reference, fast_shipped.run(stage, textures, s.receivers, query_block(block))));
      results.push_back(against(std::string("blockers of one depth, 64² map: ") + stage_name(stage) +
                                    " exports/fast_pcss with PN_AREA_EDGES, without PN_FAST_PCSS_ABLATIONS (the shipped "
                                    "walk over area-weighted squares, leaf 1) vs the definition in double on the CPU",
                                s, area_reference, fast_area.run(stage, textures, s.receivers, query_block(block)),
                                Tolerance::absolute(area_edges_rounding(kMap))));
    }
  }
  for (const auto& fixture : check_scenes(env)) {
    const Scene scene = make_scene(fixture, kMap);
    const SceneImages s = ray_cast(scene);
    const std::unique_ptr<DeviceTexture> map = env.device.upload(s.map);
    const std::string name = std::string(fixture.name) + " " + std::to_string(kMap) + "² map, " +
                             std::to_string(kScreen) + "² screen: ";
    const PcssReference exact_reference =
        exact_pcss_reference(s.map, s.gbuffer, scene.light, bias, 1.0, kPcssDecisionMargin);
    const DepthPyramid pyramid = pyramids.build(*map, kMap, kMap, 31);
    const MinMaxMipChain mip = mips.build(*map, kMap);
    const SummedAreaTable depth_sums = sums.build(*map, kMap, kMap);
    const std::vector<ExportReceiver> disks = disk_receivers(s);

    // The disks' calls: the defaults (filterScale 0: pnXDefaults), and other counts and scale.
    struct DiskCase {
      float filter_scale;
      int blocker_samples, filter_samples;
      std::vector<DiskPcssResult> poisson, vogel;
    };
    std::vector<DiskCase> disk_cases{{0.0f, PN_POISSON_BLOCKER_SAMPLES, PN_POISSON_PCF_SAMPLES, {}, {}},
                                     {0.5f, 16, 24, {}, {}}};
    const double rotation_cos = std::cos(static_cast<double>(static_cast<float>(kRotation))),
                 rotation_sin = std::sin(static_cast<double>(static_cast<float>(kRotation)));
    for (DiskCase& d : disk_cases) {
      const double scale = d.filter_scale > 0.0f ? d.filter_scale : 1.0;
      const int vogel_blockers = d.filter_scale > 0.0f ? d.blocker_samples : PN_VOGEL_BLOCKER_SAMPLES;
      const int vogel_filter = d.filter_scale > 0.0f ? d.filter_samples : PN_VOGEL_PCF_SAMPLES;
      for (std::size_t k = 0; k < disks.size(); ++k) {
        const ExportReceiver& r = disks[k];
        const DiskPcssReceiver receiver{r.u, r.v, r.depth, r.plane ? r.du : 0.0, r.plane ? r.dv : 0.0};
        // The defaults' case takes its rotation of an angle in the shader (pnPoissonRotation).
        const double trig = d.filter_scale > 0.0f ? 0.0 : 1.0 / 2048.0;
        d.poisson.push_back(disk_pcss_reference(
            s.map, scene.light, receiver, bias, scale,
            poisson_layout(blocker_disk, d.blocker_samples, rotation_cos, rotation_sin, trig),
            poisson_layout(filter_disk, d.filter_samples, rotation_cos, rotation_sin, trig)));
        const auto [px, py] = ExportPass::texel(k, disks.size());
        d.vogel.push_back(disk_pcss_reference(s.map, scene.light, receiver, bias, scale,
                                              vogel_layout(vogel_blockers, px, py), vogel_layout(vogel_filter, px, py)));
      }
    }
    // Back-projection, every texel resolved, on every third receiver (the reference is brute force);
    // and over slabs down to a second layer 0..2 deeper than the map (a hash of the texel).
    std::vector<ExportReceiver> bp_receivers;
    std::vector<DiskPcssResult> bp_expected, bp_slab_expected;
    constexpr int kBackprojectionSide = 4;
    Image second = s.map;
    for (int i = 0; i < kMap * kMap; ++i)
      second.texels[i] += 2.0f * static_cast<float>((static_cast<unsigned>(i) * 2654435761u) >> 24) / 255.0f;
    const std::unique_ptr<DeviceTexture> second_texture = env.device.upload(second);
    const MinMaxMipChain second_mip = mips.build(*second_texture, kMap);
    for (std::size_t k = 0; k < s.receivers.size(); k += 3) {
      const ExportReceiver& r = s.receivers[k];
      bp_receivers.push_back(r);
      const BackprojectionBounds b =
          backprojection_reference(s.map, scene.light, r.u, r.v, r.depth, bias, kBackprojectionSide,
                                   PN_BACKPROJECTION_DEFAULT_GAP, PN_BACKPROJECTION_DEFAULT_THICKNESS);
      bp_expected.push_back({false, b.visibility_lo, b.visibility_hi});
      const BackprojectionBounds slab =
          backprojection_slab_reference(s.map, second, scene.light, r.u, r.v, r.depth, bias, kBackprojectionSide);
      bp_slab_expected.push_back({false, slab.visibility_lo, slab.visibility_hi});
    }
    const std::vector<QueryTexture> bp_textures{{PN_EXPORT_DEPTH_MAP_BINDING, *map},
                                                {PN_EXPORT_BACKPROJECTION_MIP_BINDING, *mip.texture},
                                                {PN_EXPORT_SECOND_LAYER_BINDING, *map},
                                                {PN_EXPORT_SECOND_MIP_BINDING, *mip.texture}};
    const std::vector<QueryTexture> bp_slab_textures{{PN_EXPORT_DEPTH_MAP_BINDING, *map},
                                                     {PN_EXPORT_BACKPROJECTION_MIP_BINDING, *mip.texture},
                                                     {PN_EXPORT_SECOND_LAYER_BINDING, *second_texture},
                                                     {PN_EXPORT_SECOND_MIP_BINDING, *second_mip.texture}};

    for (const ShadeStage stage : {ShadeStage::compute, ShadeStage::fragment}) {
      const std::string where = name + stage_name(stage) + " ";
      for (const float c : {1.0f, 0.5f}) {
        glsl::PnExactPcssExport block{};
        set_light_fields(block, scene.light);
        block.bias = bias;
        block.filterScale = c;
        const PcssReference reference =
            c == 1.0f ? exact_reference : exact_pcss_reference(s.map, s.gbuffer, scene.light, bias, c, kPcssDecisionMargin);
        results.push_back(against(where + "exports/exact_pcss (pnExactPcss, c " + format_number("%g", c) +
                                      ") vs exact PCSS brute force on the CPU",
                                  s, reference, exact.run(stage, {{PN_EXPORT_DEPTH_MAP_BINDING, *map}}, s.receivers,
                                                          query_block(block))));
      }
      // PN_AREA_EDGES (issue 51): the squares with area-weighted edges, within what their
      // float edges and sums round to (pcss_compare.h).
      const PcssReference area_reference =
          exact_pcss_area_reference(s.map, s.gbuffer, scene.light, bias, 1.0, kAreaEdgeMargin);
      {
        glsl::PnExactPcssExport block{};
        set_light_fields(block, scene.light);
        block.bias = bias;
        block.filterScale = 1.0f;
        results.push_back(against(where + "exports/exact_pcss with PN_AREA_EDGES (pnExactPcss, area-weighted edges) "
                                          "vs the definition in double on the CPU",
                                  s, area_reference,
                                  exact_area.run(stage, {{PN_EXPORT_DEPTH_MAP_BINDING, *map}}, s.receivers,
                                                 query_block(block)),
                                  Tolerance::absolute(area_edges_rounding(kMap))));
      }
      const glsl::PnHqepcssExport hqepcss_block = exact_settings_block<glsl::PnHqepcssExport>(scene.light, bias, 1.0f);
      results.push_back(against(where + "exports/hqepcss (pnHqepcss: refine 0, exact regions, leaf 1) vs exact PCSS "
                                        "brute force on the CPU",
                                s, exact_reference,
                                hqepcss.run(stage, {{PN_EXPORT_PYRAMID_BINDING, *pyramid.texture},
                                                    {PN_EXPORT_DEPTH_MAP_BINDING, *map}},
                                            s.receivers, query_block(hqepcss_block))));
      results.push_back(against(where + "exports/hqepcss with PN_AREA_EDGES (pnHqepcss: refine 0, exact regions, leaf 1, "
                                        "area-weighted edges) vs the definition in double on the CPU",
                                s, area_reference,
                                hqepcss_area.run(stage, {{PN_EXPORT_PYRAMID_BINDING, *pyramid.texture},
                                                         {PN_EXPORT_DEPTH_MAP_BINDING, *map}},
                                                 s.receivers, query_block(hqepcss_block)),
                                Tolerance::absolute(area_edges_rounding(kMap))));
      const glsl::PnFastPcssExport fast_block = exact_fast_block(scene.light, bias, 1.0f);
      results.push_back(against(
          where + "exports/fast_pcss with PN_EXPORT_SUM_TABLE (pnFastPcss: refine 0, exact regions, leaf 1, table "
                  "sums) vs exact PCSS brute force on the CPU",
          s, exact_reference,
          fast_table.run(stage, {{PN_EXPORT_DEPTH_MAP_BINDING, *map}, {PN_EXPORT_FAST_MIP_BINDING, *mip.texture},
                                 {PN_EXPORT_SAMPLE_TABLE_BINDING, *table},
                                 {PN_EXPORT_SUM_TABLE_BINDING, *depth_sums.texture}},
                         s.receivers, query_block(fast_block))));
      const glsl::PnPcfExport pcf_block{bias};
      const PcssReference pcf_reference =
          pcf_plane_reference(s.map, s.gbuffer, scene.light, bias, std::ldexp(1.0, -20), 0.0);
      results.push_back(against(where + "exports/pcf (pnPcf) vs 2x2 bilinear PCF on the CPU", s, pcf_reference,
                                pcf.run(stage, {{PN_EXPORT_DEPTH_MAP_BINDING, *map}}, s.receivers,
                                        query_block(pcf_block))));
      for (const DiskCase& d : disk_cases) {
        const std::string settings = d.filter_scale > 0.0f ? format_number("c %g, ", d.filter_scale) + std::to_string(d.blocker_samples) +
                                                                 " / " + std::to_string(d.filter_samples) + " samples"
                                                           : std::string("its defaults");
        glsl::PnPoissonPcssExport pb{};
        set_light_fields(pb, scene.light);
        pb.bias = bias, pb.filterScale = d.filter_scale;
        pb.blockerSamples = d.blocker_samples, pb.filterSamples = d.filter_samples;
        pb.rotationCos = static_cast<float>(rotation_cos), pb.rotationSin = static_cast<float>(rotation_sin);
        pb.rotationAngle = static_cast<float>(kRotation), pb.rotationFromAngle = d.filter_scale > 0.0f ? 0 : 1;
        results.push_back(interval_case(where + "exports/poisson_pcss (pnPoissonPcss, " + settings +
                                            ", both overloads, rotated" +
                                            (d.filter_scale > 0.0f ? "" : " by pnPoissonRotation(angle)") +
                                            ") vs Poisson-disk PCSS on the CPU",
                                        d.poisson,
                                        poisson.run(stage, {{PN_EXPORT_DEPTH_MAP_BINDING, *map}}, disks, query_block(pb))));
        glsl::PnVogelPcssExport vb{};
        set_light_fields(vb, scene.light);
        vb.bias = bias, vb.filterScale = d.filter_scale;
        vb.blockerSamples = d.blocker_samples, vb.filterSamples = d.filter_samples;
        results.push_back(interval_case(where + "exports/vogel_pcss (pnVogelPcss, " + settings +
                                            ", both overloads) vs Vogel-disk PCSS on the CPU",
                                        d.vogel,
                                        vogel.run(stage, {{PN_EXPORT_DEPTH_MAP_BINDING, *map}}, disks, query_block(vb))));
      }
      glsl::PnBackprojectionExport bb{};
      set_light_fields(bb, scene.light);
      bb.bias = bias, bb.side = kBackprojectionSide, bb.tolerance = 0.0f, bb.budget = PN_BACKPROJECTION_MAX_BUDGET;
      bb.gap = static_cast<float>(PN_BACKPROJECTION_DEFAULT_GAP);
      bb.thickness = static_cast<float>(PN_BACKPROJECTION_DEFAULT_THICKNESS);
      results.push_back(interval_case(where + "exports/backprojection (pnBackprojection, 4 x 4 samples, every texel "
                                              "resolved) vs rays through the map's surface on the CPU",
                                      bp_expected, backprojection.run(stage, bp_textures, bp_receivers, query_block(bb))));
      glsl::PnBackprojectionExport slabs = bb;
      slabs.slabs = 1;
      results.push_back(interval_case(where + "exports/backprojection (pnBackprojection with a second layer 0..2 deeper, "
                                              "4 x 4 samples, every texel resolved) vs rays against the slabs on the CPU",
                                      bp_slab_expected,
                                      backprojection.run(stage, bp_slab_textures, bp_receivers, query_block(slabs))));

      // The shipped defaults of the calls whose defaults are not exact (sampled leaves, patches).
      glsl::PnFastPcssExport fast_defaults = exact_fast_block(scene.light, bias, 1.0f), fast_header = fast_defaults;
      fast_defaults.filterScale = 0.0f;
      fast_header.refineIterations = PN_FAST_PCSS_REFINE_ITERATIONS, fast_header.regionMode = PN_REGION_EXACT;
      fast_header.leafSide = PN_FAST_PCSS_LEAF_SIDE, fast_header.leafDivisor = PN_FAST_PCSS_LEAF_DIVISOR, fast_header.leafMode = PN_FAST_PCSS_LEAF_MODE;
      fast_header.blockerLeafMode = PN_FAST_PCSS_SAME_LEAF_MODE, fast_header.nodeBudget = PN_FAST_PCSS_NODE_BUDGET;
      fast_header.depthSums = PN_DEPTH_SUMS_MIDPOINT, fast_header.grid = PN_FAST_PCSS_GRID;
      const std::vector<QueryTexture> fast_textures{{PN_EXPORT_DEPTH_MAP_BINDING, *map}, {PN_EXPORT_FAST_MIP_BINDING, *mip.texture},
                                                    {PN_EXPORT_SAMPLE_TABLE_BINDING, *table}};
      results.push_back(defaults_case(where + "exports/fast_pcss: pnFastPcssDefaults(bias) = fast_pcss.h's defaults",
                                      fast.run(stage, fast_textures, s.receivers, query_block(fast_defaults)),
                                      fast.run(stage, fast_textures, s.receivers, query_block(fast_header))));
      // Under a light 8x as wide: regions of many leaves, so the walks descend and sample.
      LightModel wide = scene.light;
      wide.width *= 8.0;
      glsl::PnFastPcssExport shipped_wide = exact_fast_block(wide, bias, 1.0f), general_walk = fast_header;
      shipped_wide.filterScale = 0.0f;
      set_light_fields(general_walk, wide);
      general_walk.nodeBudget = PN_FAST_PCSS_NODE_BUDGET - 1;
      results.push_back(defaults_case(where + "exports/fast_pcss, the light 8x as wide: the shipped walk without "
                                              "PN_FAST_PCSS_ABLATIONS = traversal_mip.glsl's walk (a node budget of "
                                              "2^26 - 1, never reached)",
                                      fast_shipped.run(stage, fast_textures, s.receivers, query_block(shipped_wide)),
                                      fast.run(stage, fast_textures, s.receivers, query_block(general_walk))));
      glsl::PnHqepcssExport hq_defaults = hqepcss_block, hq_header = hqepcss_block;
      hq_defaults.filterScale = 0.0f;
      hq_header.refineIterations = PN_HQEPCSS_REFINE_ITERATIONS, hq_header.regionMode = PN_REGION_WINDOW;
      hq_header.leafSide = PN_HQEPCSS_LEAF_SIDE, hq_header.leafDivisor = 0, hq_header.nodeBudget = PN_TRAVERSAL_NO_BUDGET;
      const std::vector<QueryTexture> hq_textures{{PN_EXPORT_PYRAMID_BINDING, *pyramid.texture},
                                                  {PN_EXPORT_DEPTH_MAP_BINDING, *map}};
      results.push_back(defaults_case(where + "exports/hqepcss: pnHqepcssDefaults(bias) = hqepcss.h's defaults",
                                      hqepcss.run(stage, hq_textures, s.receivers, query_block(hq_defaults)),
                                      hqepcss.run(stage, hq_textures, s.receivers, query_block(hq_header))));
      glsl::PnBackprojectionExport bp_defaults = bb, bp_header = bb;
      bp_defaults.side = 0;
      bp_header.side = PN_BACKPROJECTION_DEFAULT_SIDE;
      bp_header.tolerance = static_cast<float>(PN_BACKPROJECTION_DEFAULT_TOLERANCE);
      bp_header.budget = PN_BACKPROJECTION_DEFAULT_BUDGET;
      results.push_back(defaults_case(
          where + "exports/backprojection: pnBackprojectionDefaults(bias) = backprojection.h's defaults",
          backprojection.run(stage, bp_textures, bp_receivers, query_block(bp_defaults)),
          backprojection.run(stage, bp_textures, bp_receivers, query_block(bp_header))));
    }
  }
  return results;
}

}  // namespace pn
