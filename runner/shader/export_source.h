// A module or pass as HLSL or MSL (`penumbra bundle --target hlsl|msl`): its GLSL for the vulkan
// target through glslang to SPIR-V, then SPIRV-Cross. SPIR-V keeps only what an entry point
// reaches, so a module (X.glsl, no main) is exported through its export entry, exports/X.comp:
// a compute entry that calls each overload of the module's one call once. A pass (.comp, .frag)
// is its own entry. The text starts with a comment saying how it was made, from which files
// (with each one's hash and, given, the commit) and how the GLSL bindings map to the language's
// registers.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "shader/flatten.h"
#include "shader/register_plan.h"
#include "shader/glslang_compiler.h"
#include "shader/source_tree.h"
#include "shader/spirv_cross.h"

namespace pn {

// The entry a module or pass is exported through, relative to the root: "exports/X.comp" for
// X.glsl, the pass itself otherwise. Throws Error naming the module when a module has none.
std::string export_entry(const SourceTree& tree, const std::string& module);

// A module's or pass's entry (export_entry), flattened and compiled by glslang for the vulkan target:
// what export_source crosses to HLSL or MSL and pass_interface reflects.
struct EntrySpirv {
  std::string entry;  // relative to the root
  FlatSource flat;
  std::vector<std::uint32_t> spirv;
};
// Throws Error(ExitCode::failed) with the compiler's first error.
EntrySpirv compile_entry(const GlslangProcess& process, const SourceTree& tree, const std::string& module);

// The code of an export, without its header (what `check --api hlsl` compiles back, and
// export_source writes after the header): `spirv` (compiled from `flat`) as `language`, registers
// as `plan` says, then made usable by name (issue 53) —
// - the named constants of the modules' headers (each `#define PN_X <number>` of a .h file outside
//   exports/ and passes/: PN_REGION_EXACT, PN_LEAF_QUAD, …) as `static const int|float` (MSL:
//   `constant`) before the code, so that HLSL can write `s.regionMode = PN_REGION_EXACT`;
// - each constant array of the GLSL (`const vec2 PN_EXPORT_BLOCKER_DISK[36] = …`), which
//   SPIRV-Cross names by an id (`_752`), under its GLSL name again (matched by type, length and
//   first value).
std::string export_code(const std::vector<std::uint32_t>& spirv, const FlatSource& flat, CrossLanguage language,
                        const RegisterPlan& plan);

// `provenance`: a line or two on where the files came from (the commit), put in the header.
// The header also keeps the entry's (a pass's) or the module's own leading comment.
// Throws Error(ExitCode::failed) with the compiler's first error.
std::string export_source(const GlslangProcess& process, const SourceTree& tree, const std::string& module,
                          CrossLanguage language, const std::string& provenance, const RegisterPlan& plan = {});

// The declarations of the resource at GLSL `binding` in an export's `code`, as the code spells them:
// HLSL's `… : register(xM)` lines, M = N + `plan`'s shift of the register's kind, MSL's kernel
// parameters at [[texture(N)]], [[sampler(N)]], [[buffer(N)]]. Empty when the code declares none
// (an unused resource).
std::vector<std::string> declarations_of(const std::string& code, CrossLanguage language, unsigned binding,
                                         const RegisterPlan& plan = {});


}  // namespace pn
