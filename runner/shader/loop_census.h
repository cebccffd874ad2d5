// The loop census (issue 40's GPU cost estimate): a compute pass compiled with every loop body
// counting its own runs, per invocation, into a storage buffer — how many times each loop of the
// source ran for each pixel. The same instrumented text compiled for AMD's compiler marks each
// loop in the ISA (its count's store has the constant offset 4 · (id + 1)), which is how
// isa/isa_cost.h finds the ISA loop each count belongs to (docs/isa.md, "GPU cost estimate").
#pragma once

#include <string>
#include <vector>

#include "shader/source_scan.h"
#include "shader/target.h"

namespace pn {

class GlslangProcess;  // shader/glslang_compiler.h

using CensusLoop = SourceLoop;

// Rewrites preprocessed compute-shader text: the census buffer's declaration before the first
// #line marker (`uint pnLoopCensusCounts[]` at `binding`, std430), and every for, while and
// do-while body beginning with its count: invocation k (gl_GlobalInvocationID.y · the grid's
// width + x) of a grid of loops L has loop j's count at k · (L + 1) + j + 1 (entry 0 unused).
// Returns the loops in the order of their ids. Lines keep their numbers.
std::vector<CensusLoop> census_preprocessed_loops(ShaderSource& source, unsigned binding);

// The same on `source` (a compute shader from standalone_source) after glslang's preprocessor for
// `target`. Throws Error(ExitCode::failed) with the preprocessor's first error.
std::vector<CensusLoop> census_loops(const GlslangProcess& process, ShaderSource& source, Target target,
                                     unsigned binding);

}  // namespace pn
