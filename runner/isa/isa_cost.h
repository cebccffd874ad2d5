// The GPU cost estimate's reading of an ISA (issue 40, docs/isa.md "GPU cost estimate"): each
// instruction's issue cycles on a family's SIMD (the classes and cycles of ACO's own cost tables,
// aco_statistics.cpp), the loops found from the branches (a branch back to an earlier label), and
// which loop holds each loop census count (shader/loop_census.h: loop j's count is a buffer load
// and store at `offset:4(j+1)` in its body).
#pragma once

#include <string>
#include <vector>

namespace pn {

struct IssueModel {
  bool rdna = true;  // gfx10 and later (SIMD32, issue a cycle); else GCN (SIMD16, 4 cycles)
  bool gfx11 = false;  // dual-issue of the common VALU operations in wave64
  int wave = 64;
};
// From the device, not a second list of chip names: RDNA has wave32 (`min_wave` 32, RadvNullDevice::min_wave);
// gfx11 is the family gfx11xx.
IssueModel issue_model(const std::string& family, int wave, int min_wave);

// Issue cycles of one instruction (its mnemonic, "v_fma_f32") for one wave.
double issue_cycles(const std::string& mnemonic, const IssueModel& model);
// Whether it reads memory through the vector memory path (its latency is the memory term's).
bool vector_memory_load(const std::string& mnemonic);

// What one run of some code costs a wave: issue cycles and vector memory loads.
struct CodeCost {
  double cycles = 0.0;
  double loads = 0.0;
};

struct IsaCostModel {
  CodeCost straight;                  // every instruction outside the loops (each branch side counted once)
  std::vector<CodeCost> loop_bodies;  // per census loop: one run of its ISA loop's own body (not its inner loops)
  std::vector<bool> in_loop;          // per census loop: its count lies in an ISA loop (else it was unrolled)
  int unmarked_loops = 0;             // ISA loops holding no census count (run once in the estimate)
};

// One loop of an ISA (a branch back to an earlier label), its own body: the instructions whose
// innermost loop it is (its inner loops apart), their issue cycles and vector memory loads — what
// a wave pays each time it goes round. `depth`: how many loops hold it.
struct IsaLoop {
  std::size_t depth = 0;
  double instructions = 0.0;
  double cycles = 0.0;
  double loads = 0.0;
};
// The loops of `isa` in program order (by their first instruction).
std::vector<IsaLoop> isa_loops(const std::string& isa, const IssueModel& model);

// Reads `isa` (RADV's disassembly: `BBn:` labels, one instruction a line) of a program instrumented
// with `census_loops` loops. A loop's markers (its count's load, store and the add between) are
// not counted in its cost.
IsaCostModel isa_cost_model(const std::string& isa, std::size_t census_loops, const IssueModel& model);

}  // namespace pn
