// `penumbra bench traversal`: the traversal at several leaf sizes against a
// brute-force scan of the same windows, in the same run (SPEC §9): GPU time
// per receiver, nodes and fetches per receiver, and the error of each against
// the brute-force result.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "gl/context.h"
#include "shader/source_tree.h"

namespace pn {

struct TraversalBenchRow {
  std::string method;  // "brute force", "sampled leaf 4", "min leaf 4", ...
  int leaf_side = 0;
  double gpu_ms = 0.0;  // median over repeats, whole batch
  double ns_per_receiver = 0.0;
  double nodes_per_receiver = 0.0;
  double fetches_per_receiver = 0.0;
  double speedup = 1.0;               // brute-force time / this time
  double mean_fraction_error = 0.0;   // |occluded fraction − brute force|, mean over receivers
  double max_fraction_error = 0.0;
  double mean_blocker_error = 0.0;    // |blocker mean − brute force| over receivers with blockers
};

struct TraversalBenchSetup {
  int map_size = 1024;
  int receivers = 4096;
  int repeats = 5;
  std::vector<int> leaf_sides{1, 2, 4, 8, 16};
};

// Throws Error for a map below 16, no receivers or repeats below 1.
// Throws Error naming the first bad value: map size outside 16..2048 (its pyramid: 16 N² bytes a
// level), receivers outside 1..1,000,000, repeats outside 1..1000, a leaf size outside 1..8192.
void validate_traversal_bench_setup(const TraversalBenchSetup& setup);

// Validates `setup` first (validate_traversal_bench_setup).
std::vector<TraversalBenchRow> bench_traversal(const Context& context, const SourceTree& tree,
                                               const TraversalBenchSetup& setup);

void print_traversal_bench(std::ostream& out, const TraversalBenchSetup& setup, const std::vector<TraversalBenchRow>& rows);
nlohmann::json traversal_bench_json(const TraversalBenchSetup& setup, const std::vector<TraversalBenchRow>& rows);

}  // namespace pn
