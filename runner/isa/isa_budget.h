// A technique's GPU budget, written in its module's header comment beside its call:
//   // isa budget: vgprs 32, instructions 1500, code 8192, scratch 0, loop 350, loops 900
// (loop: the costliest loop body's issue cycles a run; loops: every loop body's together: isa_cost.h)
// read for the one call as an engine compiles it, on RDNA 2 (navi21) in wave64, in both stages
// (docs/isa.md). `penumbra isa --budgets` fails on a call over its budget, and on scratch in
// any entry it compiled.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "isa/isa_run.h"
#include "shader/source_tree.h"

namespace pn {

inline constexpr const char* kBudgetFamily = "navi21";
inline constexpr int kBudgetWave = 64;

struct IsaBudget {
  std::string module;  // "fast_pcss"
  std::string file;    // "fast_pcss.glsl"
  int line = 0;
  std::vector<std::pair<std::string, double>> limits;  // "vgprs", "instructions", "code", "scratch", "loop", "loops"
};

// The module's budget line, or nothing when it has none. Throws Error naming file:line for a
// line that does not parse (an unknown key, a value that is not a number).
std::optional<IsaBudget> read_budget(const SourceTree& tree, const std::string& module);

// The budgets of every module an entry of `entries` answers to, by module (nothing for a module
// without a budget line). Throws as read_budget: read before any compile.
using IsaBudgets = std::map<std::string, std::optional<IsaBudget>>;
IsaBudgets read_budgets(const SourceTree& tree, const std::vector<IsaEntry>& entries);

// One line a breach ("fast_pcss engine compute: 3120 instructions > 1500 (fast_pcss.glsl:60)"),
// for the entries of `result` (which must be navi21 wave64).
std::vector<std::string> budget_breaches(const IsaBudgets& budgets, const std::vector<IsaProgram>& programs,
                                         const IsaTargetResult& result);

}  // namespace pn
