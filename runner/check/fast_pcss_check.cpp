// Cases of the fast_pcss check (issue 24): the PCSS family's one calls an
// engine makes — pnFastPcss (fast_pcss.glsl), pnPoissonPcss (poisson_pcss.glsl),
// pnExactPcss (exact_pcss.glsl), pnHqepcss (hqepcss.glsl) — on each scene's
// own shadow map and G-buffer:
// - in a compute pass (the runner's default path) against the staged passes
//   of the same settings: the same arithmetic in another order of passes, so
//   equal bit for bit;
// - in a fragment shader (a full-screen triangle reading the G-buffer, as a
//   deferred lighting pass runs it) against the compute pass: the same
//   arithmetic in another stage, equal bit for bit on Mesa's llvmpipe (a
//   driver may contract a * b + c into an fma in one stage and not the other:
//   docs/integration.md says what to expect there);
// - pnExactPcss, and pnFastPcss with every improvement off (refine 0, leaf 1,
//   the table's exact sums), in both stages against exact PCSS brute force on
//   the CPU (double), the pixels within rounding of a decision left out and
//   counted; pnExactPcss and pnFastPcss with every improvement off, each with
//   area-weighted edges (PN_AREA_EDGES, issue 51), against their definition
//   (exact_pcss_area_reference), within what their float edges round to
//   (pcss_compare.h), and so pnHqepcss at leaf 1 over exact regions without
//   refinement with them; the shipped pnFastPcss and pnHqepcss with
//   area-weighted edges against their staged passes and across stages as above;
// - the same calls with the receiver plane from the G-buffer's
//   neighbours (the receiverPlane overloads of pnFastPcss, pnExactPcss,
//   pnPoissonPcss, pnHqepcss): fragment vs compute, and the exact ones (exact
//   PCSS, fast with every improvement off, HQEPCSS at leaf 1 without
//   refinement over exact regions) against the brute force with the plane
//   (each texel against the plane at its centre; the staged passes take none);
// - the one call's counts (blockerNodes, occlusionNodes, fetches: its work and fetch images) for
//   the shipped walk, the work budget binding and a node budget of 4 against their definition
//   (fast_pcss_reference.h), exact, the pixels within rounding of a decision left out.
#include <string>
#include <vector>

#include "check/device_scene.h"
#include "check/module_check.h"
#include "check/pcss_compare.h"
#include "scene/scene.h"
#include "scenes.h"
#include "pipeline/pcss_pipeline.h"
#include "reference/fast_pcss_reference.h"
#include "reference/pcss_reference.h"
#include "sampling/sample_table_generator.h"

namespace pn {
namespace {

constexpr int kMap = 128, kScreen = 64;     // as the pipeline check: brute force on llvmpipe stays fast

// Channel `c` of a four-channel image.
Image channel(const Image& image, int c) {
  Image out(image.width, image.height);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) out.at(x, y) = image.at(x, y, c);
  return out;
}

// The settings the one calls are checked with: the shipped defaults, the
// shipped walk at leaf 2 with a divisor of 4 (where the work budget binds), the paper's windows with a growing leaf and min-estimated blocker leaves (every
// per-pixel option of pnFastPcss), every improvement off, Poisson PCSS, exact
// PCSS and HQEPCSS.
std::vector<PcssSettings> one_call_settings() {
  PcssSettings windows = fast_pcss();
  windows.name = "fast, windows, leaf divisor 8, min blocker leaves";
  windows.region = RegionMode::window;
  windows.leaf_side = 4;
  windows.leaf_divisor = 8;
  windows.blocker_leaf_mode = LeafMode::min;
  // The work budget where it binds on the check's 128² maps, whose regions are mostly under 64 texels
  // (fast_pcss.h: leaves of at least a region's side / the divisor): the shipped walk at leaf 2 with
  // a divisor of 4, so leaves of 4 from side 16 on, 8 from 32; quad leaves.
  PcssSettings budget = fast_pcss();
  budget.name = "fast, leaf 2, leaf divisor 4 (the work budget binding)";
  budget.leaf_side = 2;
  budget.leaf_divisor = 4;
  // A node budget spent on the way down (4 nodes, regions of more than 8 texels a side: levels >= 4),
  // the ablations' walk (pn_fastPcssAblationsEstimate) then visiting every later sibling its bound
  // allows: a walk cut short of its bound changes the counts and the visibility.
  PcssSettings node_budget = fast_pcss();
  node_budget.name = "fast, node budget 4";
  node_budget.node_budget = 4;
  PcssSettings poisson_fewer = poisson_pcss();
  poisson_fewer.name = "poisson, 16 / 32 samples, c 0.5";
  poisson_fewer.blocker_samples = 16;
  poisson_fewer.filter_samples = 32;
  poisson_fewer.filter_scale = 0.5f;
  PcssSettings grid = fast_pcss();
  grid.name = "fast, grid 4, ramp blocker leaves";
  grid.grid = 4;
  grid.blocker_leaf_mode = LeafMode::ramp;
  PcssSettings exact_area = exact_pcss();  // issue 51: the squares with area-weighted edges
  exact_area.name = "exact, area-weighted edges";
  exact_area.edges = true;
  PcssSettings fast_area = fast_pcss();
  fast_area.name = "fast, area-weighted edges";
  fast_area.edges = true;
  PcssSettings fast_all_off_area = fast_pcss_all_off();
  fast_all_off_area.name += ", area-weighted edges";
  fast_all_off_area.edges = true;
  PcssSettings hqepcss_area = hqepcss();
  hqepcss_area.name = "hqepcss, area-weighted edges";
  hqepcss_area.edges = true;
  // HQEPCSS at leaf 1 over exact regions without refinement: exact PCSS over the pyramid.
  PcssSettings hqepcss_exact = hqepcss();
  hqepcss_exact.name = "hqepcss, refine 0, leaf 1, exact regions";
  hqepcss_exact.refine_iterations = 0;
  hqepcss_exact.leaf_side = 1;
  hqepcss_exact.region = RegionMode::exact;
  PcssSettings hqepcss_exact_area = hqepcss_exact;
  hqepcss_exact_area.name += ", area-weighted edges";
  hqepcss_exact_area.edges = true;
  std::vector<PcssSettings> out{fast_pcss(),    budget,        node_budget,       windows,      grid,
                                fast_pcss_all_off(), poisson_pcss(), poisson_fewer, exact_pcss(), exact_area,
                                hqepcss(),      fast_area,     fast_all_off_area, hqepcss_area, hqepcss_exact_area};
  // With the receiver plane from the G-buffer's neighbours (receiver_plane.glsl): every one call takes one.
  for (PcssSettings s : {fast_pcss(), fast_pcss_all_off(), exact_pcss(), poisson_pcss(), hqepcss(), hqepcss_exact}) {
    s.name += ", receiver plane";
    s.receiver_plane_tan = kReceiverPlaneTan;
    out.push_back(s);
  }
  for (PcssSettings& s : out) {
    s.staged = false;  // exact PCSS and HQEPCSS run staged by default
    s.edges = s.edges.value_or(false);  // the integer squares but where named (against their own reference)
  }
  return out;
}

// Whether the settings run the shipped walk (pn_fastPcssShipped), or the ablations' with a node
// budget, over exact squares with integer edges and no plane: the walks whose counts
// fast_pcss_counts_reference defines.
bool counts_defined(const PcssSettings& s) {
  return s.blockers == Estimator::traversal && s.occlusion == Estimator::traversal && s.structure == Structure::mip &&
         s.region == RegionMode::exact && s.depth_sums == DepthSums::midpoint && s.grid == 0 && s.leaf_side >= 2 &&
         !s.blocker_leaf_mode && s.receiver_plane_tan == 0 && !s.area_edges() &&
         (s.leaf_mode == LeafMode::sampled || s.leaf_mode == LeafMode::quad);
}

// The one call's counts (its work image's Step 4 and Step 5 nodes, its fetch image) against their
// definition, the pixels where a decision lay within rounding of flipping left out: exact.
void add_count_cases(const std::string& what, const Image& map, const Image& gbuffer, const Scene& scene,
                     const PcssSettings& settings, const Image& work, const Image& fetches,
                     std::vector<CaseResult>& results) {
  FastPcssCountSettings c;
  c.bias = settings.bias, c.filter_scale = settings.filter_scale, c.refine_iterations = settings.refine_iterations;
  c.leaf_side = settings.leaf_side, c.leaf_divisor = settings.leaf_divisor, c.leaf_mode = settings.leaf_mode;
  c.node_budget = settings.node_budget;
  const FastPcssCounts expected = fast_pcss_counts_reference(map, gbuffer, scene.light,
                                                             generate_sample_table(kSampleTableSeed), c,
                                                             kPcssDecisionMargin);
  Image blocker_nodes = channel(work, 1), occlusion_nodes = channel(work, 2), observed_fetches = fetches;
  int left_out = 0;
  for (int y = 0; y < work.height; ++y)
    for (int x = 0; x < work.width; ++x)
      if (expected.ambiguous.at(x, y) != 0.0f) {
        blocker_nodes.at(x, y) = expected.blocker_nodes.at(x, y);
        occlusion_nodes.at(x, y) = expected.occlusion_nodes.at(x, y);
        observed_fetches.at(x, y) = expected.fetches.at(x, y);
        ++left_out;
      }
  const std::string tail = " vs their definition on the CPU (" + std::to_string(left_out) +
                           " pixels within rounding of a decision left out)";
  results.push_back({what + ": blockerNodes" + tail, Tolerance::exact(),
                     compare(expected.blocker_nodes, blocker_nodes, Tolerance::exact())});
  results.push_back({what + ": occlusionNodes" + tail, Tolerance::exact(),
                     compare(expected.occlusion_nodes, occlusion_nodes, Tolerance::exact())});
  results.push_back({what + ": fetches (9 a refinement, the traversals' nodes and samples)" + tail,
                     Tolerance::exact(), compare(expected.fetches, observed_fetches, Tolerance::exact())});
}

}  // namespace

std::vector<CaseResult> run_fast_pcss_check(const CheckEnvironment& env) {
  const QueryDevice& device = env.device;
  const PcssPipeline pipeline(device, env.tree);
  const auto read = [&](const DeviceTexture& t) { return device.read_texture(t, 0, 0); };
  std::vector<CaseResult> results;
  for (const auto& fixture : check_scenes(env)) {
    const Scene scene = make_scene(fixture, kMap);
    const std::string name = std::string(fixture.name) + " " + std::to_string(kMap) + "² map, " +
                             std::to_string(kScreen) + "² screen";
    const DeviceSceneFrame frame = render_device_frame(env, scene, kScreen);
    const TechniqueInputs& inputs = frame.inputs;
    const Image map = read(*frame.shadow_map), gbuffer = read(*frame.gbuffer);

    for (const PcssSettings& settings : one_call_settings()) {
      const std::string what = name + ": " + settings.name;
      const PcssFrame computed = pipeline.run(inputs, settings);
      const Image compute_work = read(*computed.work);
      const Image fragment = read(*pipeline.run_fragment(inputs, settings));
      const Image compute_visibility = read(*computed.visibility);
      const bool plane = settings.receiver_plane_tan > 0;  // the staged passes take no plane
      if (!plane) {
        PcssSettings staged_settings = settings;
        staged_settings.staged = true;
        const Image staged = read(pipeline.run(inputs, staged_settings).soft_shadow());
        results.push_back({what + ": one call in a compute pass vs the staged passes", Tolerance::exact(),
                           compare(staged, compute_visibility, Tolerance::exact())});
      }
      results.push_back({what + ": one call in a fragment shader vs the compute pass (visibility, work, flags)",
                         Tolerance::exact(), compare(compute_work, fragment, Tolerance::exact())});
      if (counts_defined(settings))
        add_count_cases(what, map, gbuffer, scene, settings, compute_work, read(*computed.fetches), results);
      const bool brute_force_equal =  // exact PCSS, and fast with every improvement off
          (settings.blockers == Estimator::scan && settings.occlusion == Estimator::scan) ||
          (settings.blockers == Estimator::traversal && settings.leaf_side == 1 && settings.refine_iterations == 0);
      if (!brute_force_equal) continue;
      const PcssReference reference =
          settings.area_edges()
              ? exact_pcss_area_reference(map, gbuffer, scene.light, settings.bias, settings.filter_scale,
                                          kAreaEdgeMargin)
              : exact_pcss_reference(map, gbuffer, scene.light, settings.bias, settings.filter_scale,
                                     kPcssDecisionMargin, settings.receiver_plane_tan);
      const Tolerance tolerance =
          Tolerance::absolute(settings.area_edges() ? area_edges_rounding(kMap) : kFractionRounding);
      for (const auto& [stage, image] : {std::pair<const char*, Image>{"compute pass", compute_visibility},
                                         std::pair<const char*, Image>{"fragment shader", channel(fragment, 0)}}) {
        Image observed = image;
        const int ambiguous = leave_out_ambiguous(reference, observed);
        results.push_back({what + ", " + stage + " vs exact PCSS brute force on the CPU (" +
                               std::to_string(ambiguous) + " pixels within rounding of a decision left out)",
                           tolerance, compare(reference.visibility, observed, tolerance)});
      }
    }
  }
  return results;
}

}  // namespace pn
