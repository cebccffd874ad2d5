#include <filesystem>
#include <iostream>
#include <set>

#include "cli/commands.h"
#include "core/error.h"
#include "shader/lint.h"

namespace fs = std::filesystem;

namespace pn::cli {
void add_lint_command(CLI::App& app, GlobalOptions& global, int& exit_code) {
  auto* cmd = app.add_subcommand("lint", "Compile each module and pass for GL 4.50, Vulkan SPIR-V and GLSL ES 3.10");
  auto paths = std::make_shared<std::vector<std::string>>();
  cmd->add_option("paths", *paths, "GLSL files or directories (default: the glsl root)");
  cmd->add_option("--glsl-root", global.glsl_root, "Directory that #include paths resolve under");
  cmd->callback([paths, &global, &exit_code] {
    if (paths->empty()) paths->push_back(glsl_root_or_default(global));
    const GlslangProcess glslang;
    size_t files = 0, failed = 0;
    // A path named more than once, or a file reached by two paths, is linted once (issue 39 C20).
    std::set<std::string> named;
    std::set<fs::path> linted;
    for (const std::string& path : *paths) {
      if (!named.insert(path).second) continue;
      const SourceTree tree(root_for(path, global));
      for (const fs::path& file : collect_glsl_files(path)) {
        std::error_code ec;
        const fs::path canonical = fs::weakly_canonical(file, ec);
        if (!linted.insert(ec ? file : canonical).second) continue;
        const LintResult result = lint_file(glslang, tree, file);
        ++files;
        for (const LintDiagnostic& d : result.diagnostics) std::cout << d.str() << "\n";
        if (!result.ok) {
          std::cout << "lint: FAIL " << result.file << "\n";
          ++failed;
        }
      }
    }
    if (files == 0) throw Error("no .glsl or .comp files found in the given paths");
    std::cout << "lint: " << files - failed << " of " << files << " files compile for gl450, vulkan and es310\n";
    exit_code = failed == 0 ? 0 : static_cast<int>(ExitCode::failed);
  });
}

}  // namespace pn::cli
