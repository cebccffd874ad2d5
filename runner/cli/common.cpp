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

}  // namespace pn::cli
