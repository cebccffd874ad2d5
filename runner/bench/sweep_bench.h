// `penumbra bench sweep`: the light's width scaled (×1, ×2, ×4, ×8 by
// default: the penumbrae grow with it) on each scene, every technique timed
// through the seam and scored against the ray-traced truth and exact PCSS by
// compare_techniques (issue 11), so that what a technique's time and quality
// do as the penumbra grows is read from one run. Exact PCSS's scan grows with
// the square of the width, so it can be left out above a factor
// (`exact_up_to`); the truth is the reference that matters.
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "bench/gpu_estimate.h"
#include "gl/context.h"
#include "scene/scene.h"
#include "shader/source_tree.h"
#include "technique/comparison.h"
#include "frame/technique.h"

namespace pn {

struct SweepBenchSetup {
  std::vector<std::string> scenes{"tall_blocker", "boxes"};
  // Non-empty: this mesh file on the ground (make_model_scene) is the one scene, named by its stem
  // in `scenes` (the command line's --model); the fixtures are not read.
  std::filesystem::path model;
  std::vector<double> factors{1, 2, 4, 8};  // multiply the fixture's light width
  std::vector<int> sizes{512};              // shadow map = screen
  int repeats = 3;
  int truth_samples = 16;
  // Exact PCSS (the registry's kExactTechnique, with or without overrides) runs only at
  // factors <= this; +Inf: at every factor. Default 2: its blocker search reads every texel of a
  // search square whose side grows with the width, and at 512² on llvmpipe (2 cores) one run
  // takes 4-8 s at x1 and 16-30 s at x2 on the tall blocker, so about a minute from x4 on.
  double exact_up_to = 2.0;
  std::vector<std::shared_ptr<const TechniqueConfig>> techniques;  // empty: render_techniques()
  std::optional<GpuEstimateSetup> estimate = GpuEstimateSetup{};  // none: no GPU cost estimate
};

// The settings the sweep and the frontier (frontier_bench.h) share: sizes in 16..4096, repeats in
// 1..100, truth samples in 1..64, exact_up_to > 0 (NaN included). Throws Error naming the first bad one.
void validate_width_bench_settings(const std::vector<int>& sizes, int repeats, int truth_samples, double exact_up_to);

// Throws Error naming the first bad setting: an unknown scene, a factor that is not a finite
// number > 0 (or that makes a light that does not validate), a size outside 16..4096, repeats
// outside 1..100, truth samples outside 1..64, exact_up_to not > 0 (NaN included), no factors,
// scenes or sizes. No GL.
void validate_sweep_setup(const SweepBenchSetup& setup);

// The fixture's scene at `size` with its light's width multiplied by `factor`; throws Error for a
// factor that is not finite and > 0, or a light that does not validate.
Scene sweep_scene(const fixtures::SceneFixture& fixture, int size, double factor);
// The same for a mesh file on the ground (make_model_scene: the box scenes' ground and light).
Scene sweep_scene(const std::filesystem::path& model, int size, double factor);

// Whether a technique names exact PCSS ("exact" or "exact:key=value…").
bool is_exact_technique(const std::string& name);

struct SweepPoint {
  std::string scene;
  int size = 0;
  double factor = 1.0;
  double light_width = 0.0;  // world units, after scaling
  Comparison comparison;     // the techniques that ran at this factor
  std::vector<GpuEstimate> estimates;  // per result of the comparison (bench/gpu_estimate.h), or none
  std::vector<double> estimate_vs_poisson;  // per result: Poisson PCSS's estimate over its own (0: none)
};

// How a technique's time changed across a scene's sweep: from its first factor with a time to
// its last (exact PCSS may stop early). ratio = ms at `to` / ms at `from`.
struct TimeGrowth {
  double from = 0.0, to = 0.0, ratio = 0.0;
};
// `factor_ms`: (factor, ms) in sweep order; pairs with a non-finite or non-positive ms are not
// counted. None when fewer than two count.
std::optional<TimeGrowth> time_growth(const std::vector<std::pair<double, double>>& factor_ms);

struct SweepBench {
  std::vector<std::string> techniques;  // every technique's name, in table order
  std::vector<SweepPoint> points;    // per scene, per size, per factor
  double exact_up_to = 2.0;
  std::optional<GpuEstimateSetup> estimate;
};

// Throws Error (validate_sweep_setup) before any GL work.
SweepBench bench_sweep(const Context& context, const SourceTree& tree, const SweepBenchSetup& setup);

// A technique's growth on one scene and size (none when it ran at fewer than two factors).
std::optional<TimeGrowth> sweep_time_growth(const SweepBench& bench, const std::string& scene, int size,
                                            const std::string& technique);

void print_sweep_bench(std::ostream& out, const SweepBench& bench);
nlohmann::json sweep_bench_json(const SweepBenchSetup& setup, const SweepBench& bench);

}  // namespace pn
