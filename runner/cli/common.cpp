#include "cli/commands.h"

namespace pn::cli {

std::string default_glsl_root() { return PENUMBRA_GLSL_DIR; }

std::string glsl_root_or_default(const GlobalOptions& global) {
  return global.glsl_root.empty() ? default_glsl_root() : global.glsl_root;
}

std::optional<Backend> chosen_backend(const GlobalOptions& global) {
  if (global.backend.empty()) return std::nullopt;
  return parse_backend(global.backend);
}

Api chosen_api(const GlobalOptions& global) { return global.api.empty() ? Api::gl450 : parse_api(global.api); }

void add_api_option(CLI::App& command, GlobalOptions& global) {
  command.add_option("--api", global.api,
                     "gl450 (OpenGL 4.5 core, the default) | es310 (OpenGL ES 3.1 on EGL: passes compiled as "
                     "`bundle --target es310` writes them)");
}

}  // namespace pn::cli
