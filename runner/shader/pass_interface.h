// A pass's (or an export's) resource interface read from its code (issue 53 item 2): what an engine
// must bind to run it — each resource's GLSL binding, HLSL register, kind, format, access, whether
// the entry uses it, and what it holds (the comment its binding carries in the pass's header).
// `penumbra bundle X --interface` prints it; the pages of the passes an engine is told to use hold
// it between `<!-- interface X -->` markers, and cli_interface_tables fails when page and code differ.
#pragma once

#include <string>
#include <vector>

#include "shader/glslang_compiler.h"
#include "shader/source_tree.h"

namespace pn {

struct InterfaceRow {
  unsigned binding = 0;
  std::string name;      // the GLSL variable or block
  std::string kind;      // "sampler2D", "image2D", "uniform block", "storage buffer", …
  std::string hlsl;      // its HLSL register(s): "t0, s0", "u2", "b3"
  std::string format;    // a storage image's declared format, else ""
  std::string access;    // "read", "write", "read-write"
  bool used = false;     // the entry uses it statically (SPIR-V's active interface): bind it, even where your path skips it
  std::string holds;     // the comment on its binding's #define or declaration, "" without one
};

// The resources of `module`'s entry (a pass, or a module's export entry), in binding order.
// Throws Error as export_source does.
std::vector<InterfaceRow> pass_interface(const GlslangProcess& process, const SourceTree& tree, const std::string& module);

// The rows as a markdown table (binding, HLSL, name, kind, format, access, used, holds).
std::string interface_markdown(const std::vector<InterfaceRow>& rows);

}  // namespace pn
