// Issue 52's yardstick on a frontier run: at every point, the shipped Fast PCSS (`fast`) against
// Poisson 36/64 (`poisson`) — its GPU estimate and llvmpipe time as ratios to Poisson's, MAE and
// SSIM against the truth side by side — and the growth of its estimate from the scene and size's
// smallest width. The goal: the estimate at most Poisson's at the smallest width and at most twice
// it at the others, the growth at most 2, and MAE <= Poisson's with SSIM >= Poisson's everywhere.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "bench/frontier_bench.h"

namespace pn {

struct FrontierGoalRow {
  std::string scene;
  int size = 0;
  double width = 1.0;
  bool first_width = false;               // the scene and size's smallest width in the run
  std::optional<double> estimate_ratio;   // fast / poisson on the GPU estimate (none: no estimate)
  double time_ratio = 0.0;                // fast / poisson, the run's medians (llvmpipe here)
  std::optional<double> growth;           // fast's estimate / its estimate at the smallest width
  double fast_mae = 0.0, poisson_mae = 0.0, fast_ssim = 0.0, poisson_ssim = 0.0;

  double cost_bound() const { return first_width ? 1.0 : 2.0; }
  bool cheap_enough() const { return estimate_ratio && *estimate_ratio <= cost_bound(); }
  bool flat_enough() const { return growth && *growth <= 2.0; }
  bool closer() const { return fast_mae <= poisson_mae && fast_ssim >= poisson_ssim; }
};

// One row a point that ran both `fast` and `poisson`, in the points' order.
std::vector<FrontierGoalRow> frontier_goal_rows(const std::vector<FrontierPoint>& points);

// The table (a row a point, each goal marked) and the count of points meeting each goal.
void print_frontier_goal(std::ostream& out, const std::vector<FrontierGoalRow>& rows);

nlohmann::json frontier_goal_json(const std::vector<FrontierGoalRow>& rows);

}  // namespace pn
