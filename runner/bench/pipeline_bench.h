// `penumbra bench pipeline`: every technique and ablation of the registry on
// one scene, through the technique seam, per stage (GPU timestamps, medians),
// at several sizes (shadow map = screen), with speed-ups against exact PCSS
// and Poisson PCSS measured in the same run and the scores of
// metrics/scores.h against the ray-traced truth and exact PCSS (SPEC §9).
#pragma once

#include <filesystem>

#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "bench/gpu_estimate.h"
#include "gl/context.h"
#include "shader/source_tree.h"
#include "technique/comparison.h"
#include "frame/technique.h"

namespace pn {

struct PipelineBenchSetup {
  std::string scene = "boxes";
  std::filesystem::path model;  // non-empty: this mesh file on the ground (scene/model.h) instead of `scene`
  std::vector<int> sizes{512, 1024};
  int repeats = 5;
  int truth_samples = 16;
  std::vector<std::shared_ptr<const TechniqueConfig>> techniques;  // empty: bench_techniques()
  std::optional<GpuEstimateSetup> estimate = GpuEstimateSetup{};  // none: no GPU cost estimate
};

struct PipelineBenchSize {
  int size = 0;
  Comparison comparison;
  // Per result: exact PCSS's / Poisson PCSS's (one pass, as engines ship it) / the staged Poisson
  // passes' total over its own (0 when that baseline did not run).
  std::vector<double> speedup_vs_exact, speedup_vs_poisson, speedup_vs_staged_poisson;  // 0: no baseline ran
  // Per result: the GPU cost estimate (bench/gpu_estimate.h; empty without one), and Poisson
  // PCSS's estimate over its own.
  std::vector<GpuEstimate> estimates;
  std::vector<double> estimate_vs_poisson;
};

// Throws Error for an unknown scene, sizes outside 16..4096, repeats < 1 or truth samples outside
// 1..64 (without GL: the command calls it before making a context).
void validate_pipeline_bench_setup(const PipelineBenchSetup& setup);

// Throws what validate_pipeline_bench_setup throws.
std::vector<PipelineBenchSize> bench_pipeline(const Context& context, const SourceTree& tree,
                                              const PipelineBenchSetup& setup);

void print_pipeline_bench(std::ostream& out, const std::vector<PipelineBenchSize>& sizes,
                          const std::optional<GpuEstimateSetup>& estimate);
nlohmann::json pipeline_bench_json(const PipelineBenchSetup& setup, const std::vector<PipelineBenchSize>& sizes);

}  // namespace pn
