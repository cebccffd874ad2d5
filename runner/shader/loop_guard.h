// Loops bounded by the runner, not by luck (issue 12): for `penumbra check`,
// every `for`, `while` and `do … while` condition of a compute shader that is not
// bounded by construction is prefixed with a call that counts the loop's
// iterations in the invocation and ends every loop once one passes a limit,
// recording which loop it was in a small storage buffer. A module copy with an endless loop then fails its
// check naming the loop's file and line instead of hanging a GPU; and since the
// counted loop has a side effect, a driver can no longer delete it as dead code
// (llvmpipe did, and the broken copy passed).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "shader/target.h"

namespace pn {

struct LoopGuardSettings {
  unsigned binding = 0;                // the storage buffer binding of the guard's state
  // Iterations one loop may run in one invocation, summed over all its entries: below
  // llvmpipe's own silent cap of 65535, so that on llvmpipe the guard speaks first.
  unsigned iterations = 65000;
};

struct GuardedLoop {
  std::string file;  // where the loop keyword is (ShaderSource::origin_of_line)
  int line = 0;
};

// Rewrites `source` (a compute shader from standalone_source) in place: the guard's
// declarations after the #version/precision/define prelude, every loop condition
// prefixed. Lines keep their numbers in the flattened part, so diagnostics still map.
// Returns the loops in the order of their ids (id k is recorded as k + 1).
std::vector<GuardedLoop> guard_loops(ShaderSource& source, const LoopGuardSettings& settings);

// The guard's state in the storage buffer: two uints, zero before a dispatch.
struct LoopGuardState {
  unsigned tripped = 0;  // 0, or 1 + the id of the first loop that passed the limit
  unsigned spare = 0;
};

// After a dispatch (`what`, e.g. "passes/blur.comp: dispatch") read back `state`: throws
// Error(ExitCode::failed) naming the loop's file and line when a loop passed `iterations`.
// Every executor reports a tripped guard with this one message.
void throw_if_loop_tripped(const LoopGuardState& state, const std::vector<GuardedLoop>& loops, unsigned iterations,
                           const std::string& what);

}  // namespace pn
