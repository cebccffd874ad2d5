#include "shader/lint.h"

#include <algorithm>

#include "core/error.h"
#include "shader/flatten.h"

namespace fs = std::filesystem;

namespace pn {

std::string LintDiagnostic::str() const {
  if (targets.empty()) return diagnostic.message;  // an include error, already "file:line: error: ..."
  std::string names;
  for (Target t : targets) names += std::string(names.empty() ? "" : ", ") + target_name(t);
  Diagnostic d = diagnostic;
  d.message = "[" + names + "] " + d.message;
  return d.str();
}

std::vector<fs::path> collect_glsl_files(const fs::path& path) {
  std::error_code ec;
  if (fs::is_regular_file(path, ec)) return {path};
  if (!fs::is_directory(path, ec)) throw Error("'" + path.string() + "': no such file or directory");
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(path, ec)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".glsl" || ext == ".comp" || ext == ".vert" || ext == ".frag"))
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

LintResult lint_file(const GlslangProcess& process, const SourceTree& tree, const fs::path& file) {
  const fs::path canonical = tree.locate(file);  // a missing argument is bad input, not a lint result
  LintResult result;
  result.file = tree.diagnostic_path(canonical);
  auto add = [&](Diagnostic d, Target target) {
    if (d.severity == "error") result.ok = false;
    for (LintDiagnostic& seen : result.diagnostics) {
      if (seen.diagnostic.file == d.file && seen.diagnostic.line == d.line && seen.diagnostic.message == d.message &&
          seen.diagnostic.severity == d.severity) {
        seen.targets.push_back(target);
        return;
      }
    }
    result.diagnostics.push_back({std::move(d), {target}});
  };

  FlatSource flat;
  try {
    flat = flatten(tree, canonical);
  } catch (const Error& e) {
    // Include errors carry their own "file:line: error:" prefix.
    result.ok = false;
    result.diagnostics.push_back({{"", 0, "error", e.what()}, {}});
    return result;
  }
  for (Target target : all_targets()) {
    const ShaderSource source = standalone_source(flat, target);
    CompileResult compiled = compile_with_glslang(process, source, target);
    for (Diagnostic d : compiled.diagnostics) {
      if (!d.file.empty() && d.file.front() != '<') d.file = tree.diagnostic_path(tree.root() / d.file);
      add(std::move(d), target);
    }
    if (!compiled.ok && compiled.diagnostics.empty())
      add({result.file, 0, "error", "compilation failed without a message"}, target);
  }
  return result;
}

}  // namespace pn
