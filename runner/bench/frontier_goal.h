// Issue 52's yardstick on a frontier run: at every point, the shipped Fast PCSS (`fast`) against
// Poisson 36/64 (`poisson`) — its GPU estimate and llvmpipe time as ratios to Poisson's, MAE and
// SSIM against the truth side by side — and the growth of its estimate from the scene and size's
// smallest width. The goal: the estimate at most Poisson's at the smallest width and at most twice
// it at the others, the growth at most 2, and MAE <= Poisson's with SSIM >= Poisson's everywhere.
// Beside them, what the work budget gave up: MAE and SSIM of the unbounded walk (kFastUnbounded),
// which bench_frontier runs with every run that has both.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "bench/frontier_bench.h"
#include "draw/line_chart.h"

namespace pn {

// Fast PCSS without its work budget (fast_pcss.h: leaves of leafSide at every width, 16 samples from
// side 8): the walk the budget is measured against, compiled as an engine that sets that budget would
// (shipped_call_settings: pnFastPcssDefaults with PN_FAST_PCSS_LEAF_DIVISOR 0 and _MODE sampled).
inline constexpr const char* kFastUnbounded = "fast:leaf-divisor=0:leaf-mode=sampled";

// The run's techniques with kFastUnbounded appended where it has `fast` and `poisson` but not it.
std::vector<std::string> with_unbounded_walk(std::vector<std::string> techniques);

struct FrontierGoalRow {
  std::string scene;
  int size = 0;
  double width = 1.0;
  bool first_width = false;               // the scene and size's smallest width in the run
  std::optional<double> estimate_ratio;   // fast / poisson on the GPU estimate (none: no estimate)
  double time_ratio = 0.0;                // fast / poisson, the run's medians (llvmpipe here)
  std::optional<double> growth;           // fast's estimate / its estimate at the smallest width
  double fast_mae = 0.0, poisson_mae = 0.0, fast_ssim = 0.0, poisson_ssim = 0.0;
  std::optional<double> unbounded_mae, unbounded_ssim;  // kFastUnbounded's, where the point ran it
  std::optional<double> unbounded_estimate_ratio;       // kFastUnbounded / poisson on the GPU estimate

  double cost_bound() const { return first_width ? 1.0 : 2.0; }
  bool cheap_enough() const { return estimate_ratio && *estimate_ratio <= cost_bound(); }
  bool flat_enough() const { return growth && *growth <= 2.0; }
  bool closer() const { return fast_mae <= poisson_mae && fast_ssim >= poisson_ssim; }
};

// One row a point that ran both `fast` and `poisson`, in the points' order.
// What frontier_goal_chart draws from: `fast` and `poisson` in the run (the registry's list has both)
// and the GPU estimate. Throws Error naming --goal-plot and what it needs.
void require_goal_inputs(const FrontierBenchSetup& setup);

std::vector<FrontierGoalRow> frontier_goal_rows(const std::vector<FrontierPoint>& points);

// The table (a row a point, each goal marked) and the count of points meeting each goal.
void print_frontier_goal(std::ostream& out, const std::vector<FrontierGoalRow>& rows);

nlohmann::json frontier_goal_json(const std::vector<FrontierGoalRow>& rows);

// Issue 52's panels (the last row of frontier_bench_chart with an estimate; `--goal-plot` alone): per
// scene and size, fast's and the unbounded walk's (kFastUnbounded) estimate / Poisson's against the
// light's width, with the goal's bound (1x at the smallest width, 2x above). Points without both
// estimates are left out.
std::vector<ChartPanel> frontier_goal_panels(const std::vector<FrontierPoint>& points);
Canvas frontier_goal_chart(const std::vector<FrontierPoint>& points, const std::string& title);

}  // namespace pn
