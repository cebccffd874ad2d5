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
  if (fs::exists(path, ec) && !fs::is_directory(path, ec))
    throw Error("'" + path.string() + "': expected a GLSL file or a directory, found a special file");
  if (!fs::is_directory(path, ec)) throw Error("'" + path.string() + "': no such file or directory");
  std::vector<fs::path> files;
  // The range-for form throws filesystem_error from operator++ on a directory it cannot
  // read; stepping with an error code names the directory instead: the entry last seen
  // is the one the failed step tried to descend into.
  fs::path last = path;
  fs::recursive_directory_iterator it(path, ec);
  for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    last = it->path();
    const std::string ext = last.extension().string();
    std::error_code type_ec;
    if (it->is_regular_file(type_ec) && (ext == ".glsl" || ext == ".comp" || ext == ".vert" || ext == ".frag"))
      files.push_back(last);
  }
  if (ec) throw Error("directory '" + last.string() + "': cannot be read (" + ec.message() + ")");
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
