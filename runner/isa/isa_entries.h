// What `penumbra isa` compiles: every technique's one call as an engine compiles it (the export's
// call with PN_EXPORT_ENGINE: the module's shipped defaults as constants, the documented
// overload), in a compute and in a fragment shader; each technique's pass as the runner runs
// it; and every pass and export entry under the glsl root as written. docs/isa.md.
#pragma once

#include <string>
#include <vector>

#include "shader/source_tree.h"
#include "shader/target.h"

namespace pn {

enum class IsaKind { engine, runner, pass };
const char* isa_kind_name(IsaKind kind);  // "engine", "runner", "pass"
IsaKind parse_isa_kind(const std::string& name);  // throws Error naming the accepted values

struct IsaEntry {
  std::string name;        // "fast_pcss" (engine), "fast" (runner), "passes/blur.comp" (pass)
  IsaKind kind = IsaKind::pass;
  Stage stage = Stage::compute;
  std::string file;        // the entry under the root: "exports/fast_pcss.comp"
  std::string vertex;      // a fragment entry's vertex shader ("passes/full_screen.vert")
  std::vector<Define> defines;
  std::string module;      // the module whose budget the entry answers to ("" for none): engine entries
  std::string label() const;  // "fast_pcss engine compute"
};

// Every entry under `tree`'s root, in a stable order: engine calls, runner calls, passes.
std::vector<IsaEntry> isa_entries(const SourceTree& tree);

}  // namespace pn
