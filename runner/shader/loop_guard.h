// Loops bounded by the runner, not by luck (issue 12): for `penumbra check`,
// every `for`, `while` and `do … while` condition of a compute shader that is not
// bounded by construction is prefixed with a call that counts the loop's
// iterations in the invocation and ends every loop once one passes a limit,
// recording which loop it was in a small storage buffer. A module copy with an endless loop then fails its
// check naming the loop's file and line instead of hanging a GPU; and since the
// counted loop has a side effect, a driver can no longer delete it as dead code
// (llvmpipe did, and the broken copy passed).
//
// The guard reads what the compiler reads (issue 39): glslang's preprocessor output for the
// target, macros expanded, comments and line continuations gone, and that guarded text is what
// is compiled. A loop a macro spells, a keyword split by `\⏎`, a directive between a keyword and
// its `(` are all plain loops there. The HLSL copies of `check --hlsl-root` get the same guard,
// written in HLSL (docs/reliability.md, "What the loop guard sees").
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "shader/source_scan.h"
#include "shader/target.h"

namespace pn {

class GlslangProcess;  // shader/glslang_compiler.h

struct LoopGuardSettings {
  unsigned binding = 0;                // the storage buffer binding of the guard's state
  // Iterations one loop may run in one invocation, summed over all its entries: below
  // llvmpipe's own silent cap of 65535, so that on llvmpipe the guard speaks first.
  unsigned iterations = 65000;
  unsigned space = 0;  // HLSL: the buffer's register space (an export in a register plan's space)
};

enum class GuardSyntax { glsl, hlsl };

using GuardedLoop = SourceLoop;

// Replaces `source.text` (a compute shader from standalone_source) by glslang's preprocessed text
// for `target` with the guard in: its declarations before the first #line marker, every loop
// condition prefixed. Lines keep their numbers, so diagnostics still map (origin_of_line).
// Returns the loops in the order of their ids (id k is recorded as k + 1). Throws
// Error(ExitCode::failed) with the preprocessor's first error (an #error, a bad directive).
std::vector<GuardedLoop> guard_loops(const GlslangProcess& process, ShaderSource& source, Target target,
                                     const LoopGuardSettings& settings);

// The same for an HLSL copy `text` (file `name`, for check's --hlsl-root): replaced by its
// preprocessed text with the guard in, in HLSL (a RWByteAddressBuffer at register u<binding>).
std::vector<GuardedLoop> guard_hlsl_loops(const GlslangProcess& process, std::string& text, const std::string& name,
                                          Stage stage, const LoopGuardSettings& settings);

// The rewrite alone, on text the preprocessor has read (the two above call it; tests too).
std::vector<GuardedLoop> guard_preprocessed_loops(ShaderSource& source, const LoopGuardSettings& settings,
                                                  GuardSyntax syntax);

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
