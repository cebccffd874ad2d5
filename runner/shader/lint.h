// `penumbra lint`: every module compiled standalone (wrapped in a minimal
// compute entry point) and every pass as it is, for GL 4.50, Vulkan → SPIR-V
// (validated) and GLSL ES 3.10.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "shader/diagnostic.h"
#include "shader/glslang_compiler.h"
#include "shader/source_tree.h"

namespace pn {

struct LintDiagnostic {
  Diagnostic diagnostic;
  std::vector<Target> targets;  // the targets that reported it
  std::string str() const;      // "file:line: error: [gl450, es310] message"
};

struct LintResult {
  std::string file;  // as printed
  bool ok = true;
  std::vector<LintDiagnostic> diagnostics;  // identical messages from several targets merged
};

// The GLSL files under `path`: the file itself, or *.glsl, *.comp, *.vert and
// *.frag below a directory, sorted. Throws Error when `path` does not exist.
std::vector<std::filesystem::path> collect_glsl_files(const std::filesystem::path& path);

LintResult lint_file(const GlslangProcess& process, const SourceTree& tree, const std::filesystem::path& file);

}  // namespace pn
