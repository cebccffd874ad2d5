#include "check/module_check.h"

#include <string_view>

#include "core/error.h"
#include "core/named.h"

namespace pn {

// Each defined in its check/<module>_check.cpp.
std::vector<CaseResult> run_blur_check(const CheckEnvironment& env);
std::vector<CaseResult> run_depth_pyramid_check(const CheckEnvironment& env);
std::vector<CaseResult> run_region_check(const CheckEnvironment& env);
std::vector<CaseResult> run_sample_table_check(const CheckEnvironment& env);
std::vector<CaseResult> run_traversal_check(const CheckEnvironment& env);
std::vector<CaseResult> run_reuse_check(const CheckEnvironment& env);
std::vector<CaseResult> run_light_model_check(const CheckEnvironment& env);
std::vector<CaseResult> run_shadow_map_check(const CheckEnvironment& env);
std::vector<CaseResult> run_pcss_regions_check(const CheckEnvironment& env);
std::vector<CaseResult> run_pipeline_check(const CheckEnvironment& env);
std::vector<CaseResult> run_pcf_check(const CheckEnvironment& env);
std::vector<CaseResult> run_poisson_pcss_check(const CheckEnvironment& env);
std::vector<CaseResult> run_vogel_pcss_check(const CheckEnvironment& env);
std::vector<CaseResult> run_receiver_plane_check(const CheckEnvironment& env);
std::vector<CaseResult> run_truth_check(const CheckEnvironment& env);
std::vector<CaseResult> run_summed_area_check(const CheckEnvironment& env);
std::vector<CaseResult> run_savsm_check(const CheckEnvironment& env);
std::vector<CaseResult> run_minmax_mip_check(const CheckEnvironment& env);
std::vector<CaseResult> run_depth_cache_check(const CheckEnvironment& env);
std::vector<CaseResult> run_cascades_check(const CheckEnvironment& env);
std::vector<CaseResult> run_vsm_check(const CheckEnvironment& env);
std::vector<CaseResult> run_fast_pcss_check(const CheckEnvironment& env);
std::vector<CaseResult> run_exports_check(const CheckEnvironment& env);
std::vector<CaseResult> run_backprojection_check(const CheckEnvironment& env);

const std::vector<ModuleCheck>& module_checks() {
  static const std::vector<ModuleCheck> checks{
      {"blur", "separable Gaussian (two 1-D passes) vs direct 2-D convolution; depth-aware vs its 1-D definition",
       &run_blur_check},
      {"depth_pyramid", "depth_pyramid levels vs window scans (min/max exact); any-square min/max vs square scans",
       &run_depth_pyramid_check},
      {"region", "region Steps 1-7 (literal and centred) vs the literal CPU steps, exhaustive on small maps",
       &run_region_check},
      {"sample_table", "multi-jittered strata of the table; the 3.2 selection and scaling vs the paper's arithmetic",
       &run_sample_table_check},
      {"traversal", "leaf 1 vs brute force (exact counts); sampled / min leaves and budgets vs the CPU recursion",
       &run_traversal_check},
      {"reuse", "parent links, representatives and gathered values vs explicit parent pointers and root finding",
       &run_reuse_check},
      {"light_model", "blocker-window, search-width and penumbra widths vs runner/scene/light_model.h",
       &run_light_model_check},
      {"shadow_map", "each scene's shadow map and G-buffer vs CPU ray casts through every texel / pixel centre",
       &run_shadow_map_check},
      {"pcss_regions", "search entries (lit decisions, refined sides), filter entries and their regions in every mode vs "
                       "the CPU definition; no lit receiver a texel can shadow (exact mode)",
       &run_pcss_regions_check},
      {"pipeline", "exact PCSS vs CPU brute force; all improvements off == exact PCSS; bad inputs; SSIM at 512^2",
       &run_pipeline_check},
      {"fast_pcss", "pnFastPcss, pnPoissonPcss, pnExactPcss, pnHqepcss as one call: compute pass vs the staged passes "
                    "and fragment shader vs compute pass (exact); exact and all-off vs exact PCSS brute force on the CPU",
       &run_fast_pcss_check},
      {"pcf", "brute-force window scan (whole, banded, bounded side) vs the definition in double; counts exact",
       &run_pcf_check},
      {"poisson_pcss", "Poisson-disk samples (parameter and constant disks, rotation) vs the definition in double",
       &run_poisson_pcss_check},
      {"vogel_pcss", "Vogel-disk samples (counts 1..128, turns) and the interleaved-gradient-noise rotation vs the "
                     "definition in double, within GPU sin/cos error",
       &run_vogel_pcss_check},
      {"receiver_plane", "receiver-plane gradient from G-buffer neighbours (edges, invalid and singular steps, clamps) "
                         "and its range over rectangles vs the definition in double",
       &run_receiver_plane_check},
      {"truth", "Embree ray-traced truth vs slab tests on the same rays; width 0 == one shadow ray; converges in S",
       &run_truth_check},
      {"summed_area", "64-bit fixed-point summed-area tables: depth and moment sums vs direct box sums (exact), float "
                      "sums, means and variances in bound; the float moments table's errors beside the fixed one's",
       &run_summed_area_check},
      {"minmax_mip", "aligned min/max mip chain levels (padded to a power of two) vs node scans (exact)",
       &run_minmax_mip_check},
      {"depth_cache", "min(static, dynamic) and its shadow test vs the definition; both caches over 100-frame motion "
                      "sequences vs a full render (map, mip chain, pyramid, Fast PCSS: exact)",
       &run_depth_cache_check},
      {"cascades", "split positions (practical, hybrid, adaptive lambda) and their order, selection and blend weights, "
                   "slice spheres and snaps vs the definitions in double; stable cascades move by whole texels",
       &run_cascades_check},
      {"exports", "the export entries (what bundle --target hlsl|msl translates) as query passes: pnExactPcss vs exact "
                  "PCSS brute force, pnPcf vs 2x2 bilinear PCF on the CPU, both overloads",
       &run_exports_check},
      {"backprojection", "the light's visible fraction through the height field (bitmask of light samples, every "
                         "texel resolved) vs the ray march on the CPU, area light and sun; patches within a stated bound",
       &run_backprojection_check},
      {"vsm", "VSM / EVSM moments, blurred moments vs direct 2-D sums, Chebyshev and bleeding reduction vs double, "
              "depth-range bound vs window scans (exact); light bleeding vs exact PCF on two occluders",
       &run_vsm_check},
      {"savsm", "summed-area variance soft shadows: squares, blocker, filter side, moments and visibility vs the "
                "estimate in double from brute-force moments over the same rectangles; fetches per receiver (constant)",
       &run_savsm_check},
  };
  return checks;
}

std::vector<fixtures::SceneFixture> check_scenes(const CheckEnvironment& env) {
  std::vector<fixtures::SceneFixture> out;
  for (const fixtures::SceneFixture& f : fixtures::kScenes)
    if (!env.options.quick || f.name == std::string_view("tall_blocker")) out.push_back(f);
  return out;
}

std::vector<fixtures::TextureFixture> check_texture_fixtures(const CheckEnvironment& env) {
  std::vector<fixtures::TextureFixture> out;
  for (const fixtures::TextureFixture& f : fixtures::kTextureFixtures)
    if (!env.options.quick || f.name == std::string_view("step_edge") || f.name == std::string_view("nonfinite") ||
        f.name == std::string_view("boxes"))
      out.push_back(f);
  return out;
}

const ModuleCheck& find_module_check(const std::string& module) {
  return find_named(module_checks(), module, "module '" + module + "': no check registered");
}

}  // namespace pn
