#include "cli/commands.h"

#include "core/error.h"

namespace pn::cli {

// An installed tool's own modules (cmake --install puts them at PENUMBRA_GLSL_DIR_FROM_BIN, relative to the
// binary's directory); a tool in its build tree finds none there and reads the checkout it was built from.
std::string default_glsl_root() {
  std::error_code ec;
  const std::filesystem::path installed =
      std::filesystem::read_symlink("/proc/self/exe", ec).parent_path() / PENUMBRA_GLSL_DIR_FROM_BIN;
  if (!ec && std::filesystem::is_directory(installed, ec)) return installed.lexically_normal().string();
  return PENUMBRA_GLSL_DIR;
}

std::string glsl_root_or_default(const GlobalOptions& global) {
  return global.glsl_root.empty() ? default_glsl_root() : global.glsl_root;
}

std::filesystem::path root_for(const std::filesystem::path& path, const GlobalOptions& global) {
  namespace fs = std::filesystem;
  if (!global.glsl_root.empty()) return global.glsl_root;
  std::error_code ec;
  const fs::path library = fs::canonical(default_glsl_root(), ec);
  const fs::path target = fs::canonical(path, ec);
  if (ec) throw Error("'" + path.string() + "': no such file or directory");
  const fs::path rel = target.lexically_relative(library);
  if (!library.empty() && !rel.empty() && *rel.begin() != "..") return library;
  const fs::path directory = fs::is_directory(target) ? target : target.parent_path();
  // A pass of a copy (my-copy/passes/x.comp, or an export entry my-copy/exports/x.comp, issue 39 C17)
  // includes the copy's modules: the copy is the root.
  const bool in_copy = directory.filename() == "passes" || directory.filename() == "exports";
  return in_copy && !fs::is_directory(target) ? directory.parent_path() : directory;
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

void add_register_plan_options(CLI::App& command, RegisterPlanOptions& options, const std::string& where) {
  command.add_option("--register-shift", options.shift,
                     where + ": your register plan's shifts, added to each GLSL binding by register kind: t (textures, "
                             "read-only buffers), s (samplers), u (images, read-write buffers), b (constant buffers), "
                             "e.g. t=16,u=32,b=48 (each 0 to " + std::to_string(kMaxRegisterShift) + "; default 0)");
  command.add_option("--register-space", options.space,
                     where + ": the register space of every resource (0 to " + std::to_string(kMaxRegisterSpace) +
                         "; default 0), a descriptor set on Vulkan");
}

RegisterPlan register_plan_of(const RegisterPlanOptions& options, bool applies, const std::string& what) {
  if (options.given() && !applies)
    throw Error(std::string(options.shift.empty() ? "--register-space" : "--register-shift") + ": applies to " + what +
                " only");
  return parse_register_plan(options.shift, options.space.value_or(0));
}

}  // namespace pn::cli
