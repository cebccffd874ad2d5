// What a loop census gathers (shader/loop_census.h): one record a dispatch of an instrumented
// compute pass — which pass, with which defines, its loops, its grid, and for each wave of 64 and
// of 32 invocations (consecutive local invocation indices of a work group, as AMD's hardware
// packs them) the most runs of each loop by one of its invocations: a wave runs a loop until its
// last invocation leaves it. `bench` turns the records into the GPU cost estimate
// (bench/gpu_estimate.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "shader/loop_census.h"
#include "shader/target.h"

namespace pn {

struct CensusWaves {
  int size = 64;                       // invocations a wave
  std::vector<std::uint32_t> most;     // wave w, loop j at w · loops + j
};

struct LoopCensusRecord {
  std::string pass;              // "passes/pcss_one_call.comp"
  std::vector<Define> defines;   // as compiled
  std::vector<CensusLoop> loops;
  int local_size[3] = {1, 1, 1};
  int groups[2] = {0, 0};        // work groups in x and y (z is 1 in every census'd pass)
  std::vector<double> mean;      // each loop's runs per invocation, over the grid
  CensusWaves waves[2] = {{64, {}}, {32, {}}};

  int invocations() const { return groups[0] * local_size[0] * groups[1] * local_size[1]; }
  const CensusWaves& of_wave(int size) const { return waves[size == 32 ? 1 : 0]; }
};

// Fills `r`'s means and wave maxima from the dispatch's count buffer (`counts`: invocation k,
// loop j at k · (loops + 1) + j + 1; k = gl_GlobalInvocationID.y · the grid's width + x).
void reduce_census_counts(LoopCensusRecord& r, const std::vector<std::uint32_t>& counts);

// The records of the dispatches made while it was the context's census (Context::set_loop_census).
struct LoopCensus {
  std::vector<LoopCensusRecord> records;
};

}  // namespace pn
