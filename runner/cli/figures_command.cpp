#include <iostream>

#include "cli/commands.h"
#include "core/write_file.h"
#include "figures/figures.h"

namespace pn::cli {

void add_figures_command(CLI::App& app, GlobalOptions& global, int& exit_code) {
  auto out = std::make_shared<std::string>("docs/images");
  auto* cmd = app.add_subcommand("figures", "Draw the docs' pictures from what the modules compute on the GPU");
  cmd->add_option("--out", *out, "Directory for the PNG files (default docs/images)");
  cmd->add_option("--glsl-root", global.glsl_root, "Draw from the modules in this directory");
  cmd->add_option("--backend", global.backend, "egl-device | egl-surfaceless | osmesa (default: first that works)");
  cmd->callback([out, &global, &exit_code] {
    validate_output_directory(*out);  // before the context: a bad --out is exit 2 with or without one
    // One that cannot be written, or a picture's name there that cannot be (issue 39 C8, C9).
    if (std::filesystem::is_directory(*out)) prepare_output_directory(*out, figure_file_names());
    const SourceTree tree(glsl_root_or_default(global));
    const auto context = create_context(chosen_backend(global));
    for (const auto& path : write_figures(*context, tree, *out)) std::cout << "wrote " << path.string() << "\n";
    exit_code = 0;
  });
}

}  // namespace pn::cli
