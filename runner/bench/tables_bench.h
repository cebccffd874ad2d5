// `penumbra bench tables`: GPU build time and memory of glsl/summed_area.glsl's
// tables from the same shadow map, interleaved in the same run: the depth-sum
// table (SummedAreaPass: 64-bit sums of depth and finite counts, what the
// exact-region traversal reads) and the two moments tables
// (SummedAreaMomentsPass: fixed point Σq, Σq² modulo 2^64, and float Σ(x − ½),
// Σ(x − ½)² — what the summed-area VSM reads).
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "gl/context.h"
#include "shader/source_tree.h"

namespace pn {

struct TableBuildTime {
  std::size_t bytes = 0;  // the table (the build's row-prefix table, as large, lives only while building)
  double gpu_ms = 0.0;    // median GPU time of a whole build (both passes)
  double wall_ms = 0.0;   // median wall time to glFinish, the allocations included
};

struct TablesBenchRow {
  int size = 0;
  int repeats = 0;
  TableBuildTime depth, fixed, floating;
};

// Throws Error naming the first bad value: a size outside 1..4096 (a 4096² fixed table and its
// row-prefix table take 512 MiB), repeats outside 1..1000, more than 32 sizes.
void validate_tables_bench(const std::vector<int>& sizes, int repeats);

// Validates its arguments first (validate_tables_bench). The map: the noise fixture as light
// depths 20 + 20 v in the moments tables' range [1, 100].
std::vector<TablesBenchRow> bench_tables(const Context& context, const SourceTree& tree, const std::vector<int>& sizes,
                                         int repeats);

void print_tables_bench(std::ostream& out, const std::vector<TablesBenchRow>& rows);
nlohmann::json tables_bench_json(const std::vector<TablesBenchRow>& rows);

}  // namespace pn
