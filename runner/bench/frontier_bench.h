// `penumbra bench frontier` (issue 25): which technique gives the best shadow
// for a frame budget, and does that change when the light widens? Per scene ×
// map size × light width, every technique at several budgets (the Poisson and
// Vogel disks at 8–128 taps, Fast PCSS over its leaf settings, HQEPCSS,
// SAVSM, VSM / EVSM, PCF, exact PCSS where affordable) is timed as engines run
// it (its one call and its per-frame structures, interleaved rounds, medians)
// and scored on light-facing pixels against the ray-traced truth; the Pareto
// frontier of time against MAE is drawn, and Fast PCSS's default is asked
// whether another technique reaches its MAE in less time. Beside each time,
// the GPU cost proxy (frame/fetch_proxy.h): texel fetches per pixel and the
// mean of each 8×8 tile's maximum.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "draw/canvas.h"
#include "metrics/scores.h"
#include "bench/gpu_estimate.h"
#include "gl/context.h"
#include "shader/source_tree.h"

namespace pn {

struct FrontierBenchSetup {
  // boxes, fence, tall_blocker (area light), spider (the Assimp model on the ground), city (the sun,
  // on kFrontierCascades cascades).
  std::vector<std::string> scenes{"boxes", "fence", "tall_blocker", "spider", "city"};
  // Non-empty: this mesh file on the ground (make_model_scene, the box scenes' light) is the one
  // scene, named by its stem in `scenes` (the command line's --model; issue 52 item 4).
  std::filesystem::path model;
  std::vector<double> widths{1, 2, 4, 8};  // light width factors
  // Shadow-map sizes (each cascade's map on the city): 256² is where engines' spot lights live (atlas
  // tiles), and where the filter's edge decides (issue 51).
  std::vector<int> sizes{256, 512, 1024};
  std::optional<int> screen;  // the screen's side; none: the map's (each point's size)
  int repeats = 3;
  int truth_samples = 16;
  // Exact PCSS and HQEPCSS (their PCF reads every texel of the filter region, which grows as the
  // width²: at 512² ×8 one HQEPCSS frame takes about a minute on llvmpipe) only at factors <= this.
  double exact_up_to = 2.0;
  std::vector<std::string> techniques;   // empty: frontier_techniques() (the registry)
  std::optional<GpuEstimateSetup> estimate = GpuEstimateSetup{};  // none: no GPU cost estimate
};

inline constexpr int kFrontierCascades = 3;
inline constexpr const char* kFrontierDefault = "fast";  // the configuration the frontier is asked about

// `--quick`: boxes and the tall blocker at 128² and 256², widths 1 and 4, one round, 4² truth
// samples, and a configuration of each technique family (short enough for CI).
FrontierBenchSetup quick_frontier_setup();

// Throws Error naming the first bad setting (unknown scene, bad width, size outside 16..4096,
// repeats outside 1..100, truth samples outside 1..64, a bad technique). No GL; reads the model.
void validate_frontier_setup(const FrontierBenchSetup& setup);

struct FrontierRow {
  std::string technique, family;  // family: the registry name ("poisson", "vogel", "fast", ...)
  double ms = 0.0;             // GPU time of the technique's frame (structures + call), median
  double ssim = 0.0, mae = 0.0;  // light-facing pixels vs the truth
  BiasErrors bias;               // acne and leak on them (metrics/scores.h)
  std::optional<double> fetches, tile_max;  // the cost proxy, where the technique counts its fetches
  bool on_frontier = false;    // no other row is as fast and as close, and strictly better in one
  std::optional<double> estimate_ms;  // the GPU cost estimate (bench/gpu_estimate.h), where there is one
  bool on_estimate_frontier = false;  // the same frontier with estimate_ms for the time (every row has one)
};

struct FrontierPoint {
  std::string scene;
  int size = 0;
  int screen = 0;      // the screen's side it was scored on
  double width = 1.0;  // factor
  std::vector<FrontierRow> rows;
  // The default's standing: the fastest row of another family with MAE <= the default's and less
  // time, if any.
  std::optional<FrontierRow> beats_default;
  std::optional<FrontierRow> beats_default_estimate;  // the same by estimate_ms
};

std::vector<FrontierPoint> bench_frontier(const Context& context, const SourceTree& tree, const FrontierBenchSetup& setup);

// Marks rows on the Pareto frontier and finds what beats the default (no GL; the bench calls it).
void mark_frontier(FrontierPoint& point);

// The point's row of `technique` (kFrontierDefault, kPoissonTechnique, ...), or none.
const FrontierRow* frontier_row(const FrontierPoint& point, const std::string& technique);

void print_frontier_bench(std::ostream& out, const std::vector<FrontierPoint>& points,
                          const std::optional<GpuEstimateSetup>& estimate);
nlohmann::json frontier_bench_json(const FrontierBenchSetup& setup, const std::vector<FrontierPoint>& points);
// One panel per scene × width (a row of panels per scene and size), time (log) against MAE, each
// family's configurations as points, the frontier drawn, the default marked; with `estimate`,
// the same panels again below with the GPU cost estimate for the time.
Canvas frontier_bench_chart(const std::vector<FrontierPoint>& points, const std::string& title,
                            const std::optional<GpuEstimateSetup>& estimate);

}  // namespace pn
