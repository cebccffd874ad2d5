// The GPU cost estimate beside every bench time (issue 40; docs/isa.md "GPU cost estimate"): each
// technique's compute dispatches run once more with their loops counted (the loop census), the same
// passes compiled by AMD's compiler (RADV's null device) with the same counts in them so that each
// count finds its ISA loop, and per wave
//   cycles = straight + Σ_loops (most runs by one of the wave's invocations) × body
//          + (vector memory loads executed) × 320 / (waves a SIMD holds at the pass's VGPRs),
// summed over the waves of every dispatch and spread over a reference card's SIMDs at its clock.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <map>
#include <memory>
#include <optional>
#include <ostream>

#include "device/loop_census_record.h"
#include "shader/source_tree.h"
#include "technique/comparison.h"

namespace pn {

struct GpuEstimateSetup {
  std::string family = "navi21";
  int wave = 64;
};
// `--estimate`'s value: "FAMILY" (wave64), "FAMILY/32" or "off" (none). Throws Error naming the forms.
std::optional<GpuEstimateSetup> parse_gpu_estimate(const std::string& value);
std::string gpu_estimate_label(const GpuEstimateSetup& setup);  // "navi21 wave64"

// The reference card of a family the milliseconds are for: its SIMDs and clock.
struct ReferenceCard {
  std::string name;
  int simds = 0;
  double clock_ghz = 0.0;
};
// Throws Error naming the families it knows.
ReferenceCard reference_card(const std::string& family);

struct LoopEstimate {
  std::string where;          // "traversal.glsl:512"
  bool in_loop = false;       // its count lies in an ISA loop (else unrolled: in the straight part)
  double mean_runs = 0.0;     // per invocation
  double mean_wave_most = 0.0;  // per wave: the most runs by one of its invocations
  double body_cycles = 0.0;   // one run of its ISA loop's own body
};

struct PassEstimate {
  std::string pass;           // "passes/pcss_one_call.comp"
  int dispatches = 0;
  double waves = 0.0;         // over its dispatches
  double vgprs = 0.0, waves_per_simd = 0.0;
  double straight_cycles = 0.0, loop_cycles = 0.0, memory_cycles = 0.0;  // summed over its waves
  int unmarked_loops = 0;
  std::vector<LoopEstimate> loops;
};

struct GpuEstimate {
  bool ok = false;
  std::string error;          // why there is none ("" when ok): no radeon ICD, a pass that failed
  double cycles = 0.0;        // every wave of every dispatch
  double ms = 0.0;            // on the reference card
  std::vector<PassEstimate> passes;
};

// Estimates censuses for one family and wave size. Each distinct pass and defines is compiled
// once an estimator (the new ones of a call in one child process). Never throws for a driver or
// ICD problem: the estimates say it in `error`.
class GpuEstimator {
 public:
  GpuEstimator(const SourceTree& tree, const GpuEstimateSetup& setup);
  const GpuEstimateSetup& setup() const { return setup_; }
  // One estimate a census, in their order.
  std::vector<GpuEstimate> estimate(const std::vector<const LoopCensus*>& censuses);
  // The estimates of a comparison's techniques (run with ComparisonSetup::census), in its order;
  // their censuses are emptied: the estimates keep what they need.
  std::vector<GpuEstimate> estimate(Comparison& comparison);

 private:
  struct Compiled;
  SourceTree tree_;
  GpuEstimateSetup setup_;
  std::map<std::string, std::shared_ptr<const Compiled>> compiled_;  // by pass and defines
};

nlohmann::json gpu_estimate_json(const GpuEstimate& e, const GpuEstimateSetup& setup);

// A table's two estimate cells for result `i`: its estimated µs and `ratios[i]` ("-" where none).
void print_estimate_cells(std::ostream& out, const std::vector<GpuEstimate>& estimates,
                          const std::vector<double>& ratios, std::size_t i);
// The line under a table: what the estimate is for, and each estimate that failed, why.
void print_estimate_note(std::ostream& out, const GpuEstimateSetup& setup, const std::vector<GpuEstimate>& estimates);
// The estimate of `technique`'s result in `comparison` (null when it did not run or has none).
const GpuEstimate* estimate_of(const Comparison& comparison, const std::vector<GpuEstimate>& estimates,
                               const std::string& technique);
// Estimated time of `base` over each result's (0 where either has none): as the bench's time ratios.
std::vector<double> estimate_ratios(const Comparison& comparison, const std::vector<GpuEstimate>& estimates,
                                    const std::string& base);
// A ratio of the bench's (a time or an estimate over a baseline's; 0 where either did not run) as
// JSON: null where there is none (issue 54 X15: 0.0 read as a measured ratio).
nlohmann::json ratio_json(double ratio);

}  // namespace pn
