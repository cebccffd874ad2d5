// `penumbra bench pyramid`: GPU build time of the decreased pyramid against
// the aligned min/max mip chain, and of the structure Fast PCSS traverses by
// default (the mip chain and the summed-area table of depth), measured in the
// same run (SPEC §9).
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "gl/context.h"
#include "shader/source_tree.h"

namespace pn {

struct PyramidBenchRow {
  int size = 0;
  int levels = 0;
  std::size_t pyramid_bytes = 0;
  double pyramid_ms = 0.0;       // median GPU time
  double pyramid_wall_ms = 0.0;  // median wall time to glFinish
  std::size_t mip_bytes = 0;
  double mip_ms = 0.0;
  double mip_wall_ms = 0.0;
  // The build's first dispatch alone (node level 2 from the map), and the rest (levels 3 to log2 P,
  // one dispatch each): the median over rounds of the whole build less the first dispatch, timed in
  // the same round. The rest bounds what one single-dispatch build (AMD's SPD: every level in group
  // memory) could save here.
  double mip_first_ms = 0.0;
  double mip_rest_ms = 0.0;
  int mip_dispatches = 0;
  std::size_t sums_bytes = 0;  // the summed-area table of depth (summed_area.glsl)
  double sums_ms = 0.0;        // median GPU time of its build
  int repeats = 0;
};

// Throws Error naming the first bad value: a size outside 2..4096 (the pyramid: 16 N² bytes a
// level, 3.5 GiB at 4096²), repeats outside 1..1000, max_level < 0.
void validate_pyramid_bench(const std::vector<int>& sizes, int repeats, int max_level);

// Validates its arguments first (validate_pyramid_bench).
std::vector<PyramidBenchRow> bench_pyramid(const Context& context, const SourceTree& tree, const std::vector<int>& sizes,
                                           int repeats, int max_level);

void print_pyramid_bench(std::ostream& out, const std::vector<PyramidBenchRow>& rows);
nlohmann::json pyramid_bench_json(const std::vector<PyramidBenchRow>& rows);

}  // namespace pn
