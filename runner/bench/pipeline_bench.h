// `penumbra bench pipeline`: every PCSS technique and every Fast PCSS
// ablation on one scene, per stage (GPU timestamps, medians), at several
// sizes (shadow map = screen), with speedups against exact PCSS and Poisson
// PCSS measured in the same run, SSIM against exact PCSS, the fraction of
// representatives and the work per receiver pixel (SPEC §9).
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "gl/context.h"
#include "pipeline/pcss_settings.h"
#include "shader/source_tree.h"

namespace pn {

struct PipelineBenchSetup {
  std::string scene = "boxes";
  std::vector<int> sizes{512, 1024};
  int repeats = 5;
  std::vector<PcssSettings> methods;  // empty: pcss_methods() then fast_pcss_ablations() without all-off
};

struct PipelineBenchRow {
  int size = 0;
  std::string method;
  double total_ms = 0.0;  // median, Steps 1 (pyramid) .. 6
  std::vector<std::pair<std::string, double>> stage_ms;
  double speedup_vs_exact = 0.0;    // 0 when exact PCSS was not run
  double speedup_vs_poisson = 0.0;  // 0 when Poisson PCSS was not run
  double ssim_vs_exact = 0.0;       // soft-shadow maps
  double lit_ssim_vs_exact = 0.0;   // lit images (figures/lit_image.h)
  double representative_fraction = 0.0;
  double work_per_receiver = 0.0;   // nodes (traversal), texels (scan) or samples (Poisson)
};

// Throws Error for an unknown scene, sizes outside 16..4096 or repeats < 1.
std::vector<PipelineBenchRow> bench_pipeline(const Context& context, const SourceTree& tree, PipelineBenchSetup setup);

void print_pipeline_bench(std::ostream& out, const std::vector<PipelineBenchRow>& rows);
nlohmann::json pipeline_bench_json(const PipelineBenchSetup& setup, const std::vector<PipelineBenchRow>& rows);

}  // namespace pn
