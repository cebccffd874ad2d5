// `penumbra isa`'s work: the entries compiled to SPIR-V once (glslang, the vulkan target), then
// for each target (a chip family and a wave size) a child process that sets RADV's environment,
// opens the null device and compiles every entry there; the children write their results to
// files the parent reads, so a driver crash costs one target, not the run.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "isa/isa_cost.h"
#include "isa/isa_entries.h"
#include "isa/radv_null.h"
#include "shader/glslang_compiler.h"

namespace pn {

struct IsaProgram {
  IsaEntry entry;
  std::vector<std::uint32_t> spirv;   // the entry's stage
  std::vector<std::uint32_t> vertex;  // a fragment entry's vertex shader
};

// Throws Error(ExitCode::failed) "file:line: error: …" for an entry that does not compile.
std::vector<IsaProgram> compile_isa_programs(const GlslangProcess& glslang, const SourceTree& tree,
                                             const std::vector<IsaEntry>& entries);

// The figures of one shader that the table, the budgets and the JSON read.
struct IsaFigures {
  double vgprs = 0, sgprs = 0, spilled_vgprs = 0, spilled_sgprs = 0, scratch = 0, code = 0, instructions = 0,
         branches = 0, image = 0, latency = 0, throughput = 0, waves = 0;
  std::vector<IsaLoop> loops;  // each loop's own body, in program order (isa_cost.h)
  double loop_cycles_max = 0, loop_cycles_sum = 0;  // the costliest loop body, and every body together
};
// `e`'s figures: the driver's statistics, image instructions counted in its ISA, its loops costed
// for `family` (isa_cost.h), and waves per SIMD in waves of `wave` lanes (RADV counts subgroups in
// wave32 units on a device with wave32, `min_wave` 32: gfx10 and later).
IsaFigures isa_figures(const ShaderExecutable& e, const std::string& family, int wave, int min_wave);

struct IsaShader {
  std::string error;                        // the pipeline did not compile ("" when it did)
  std::vector<ShaderExecutable> executables;
  // The executable of the entry's own stage (nullptr when none): a fragment entry's vertex
  // shader is compiled too but is not the entry.
  const ShaderExecutable* own(Stage stage) const;
};

struct IsaTargetResult {
  RadvTarget target;
  std::string device;                 // "Null hardware (RADV NAVI21)"
  int min_wave = 64;                  // the device's least subgroup size (RadvNullDevice::min_wave)
  std::string error;                  // the target did not run at all ("" when it did)
  std::vector<IsaShader> shaders;     // one an entry, in the programs' order
};

// Targets a family does not support (wave32 before gfx10) are not run: `supports_wave`.
bool supports_wave(const std::string& family, int wave);

// Runs every target, `jobs` child processes at a time; `progress` hears one line a target done.
// Throws Error(ExitCode::failed) when the radeon ICD is not installed.
std::vector<IsaTargetResult> run_isa(const std::vector<IsaProgram>& programs, const std::vector<RadvTarget>& targets,
                                     int jobs, const std::function<void(const std::string&)>& progress);

// Throws Error (exit 2) naming the first of `families` RADV cannot make a device of (issue 54 X3:
// an unknown name compiled everything, then the driver aborted): one device a family, made by
// run_isa with no program (a fraction of a second each), before any compiling.
void require_radv_families(const std::vector<std::string>& families, int jobs);

}  // namespace pn
