// The subcommands of `penumbra`; each returns the process exit code and
// throws pn::Error for bad input.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>

#include "gl/context.h"
#include "shader/register_plan.h"

namespace pn::cli {

// Options shared by the commands that need them.
struct GlobalOptions {
  std::string glsl_root;  // empty: the library's own glsl/
  std::string backend;    // empty: first that works
  std::string api;        // empty: gl450
};

// The whole command line: parses argv, runs the command, reports every error as one line
// `penumbra: error: …` on standard error; returns the exit code (0, 1 failed, 2 bad input,
// 3 no context).
int run(int argc, char** argv);

void add_lint_command(CLI::App& app, GlobalOptions& global, int& exit_code);
void add_bundle_command(CLI::App& app, GlobalOptions& global, int& exit_code);
void add_check_command(CLI::App& app, GlobalOptions& global, int& exit_code);
void add_info_command(CLI::App& app, GlobalOptions& global, int& exit_code);
void add_bench_command(CLI::App& app, GlobalOptions& global, int& exit_code);
void add_figures_command(CLI::App& app, GlobalOptions& global, int& exit_code);
void add_poisson_command(CLI::App& app, int& exit_code);
void add_sample_table_command(CLI::App& app, int& exit_code);
void add_techniques_command(CLI::App& app, int& exit_code);
void add_render_command(CLI::App& app, GlobalOptions& global, int& exit_code);
void add_isa_command(CLI::App& app, GlobalOptions& global, int& exit_code);

// Helpers for the commands.
std::string default_glsl_root();
std::string glsl_root_or_default(const GlobalOptions& global);
// The root a module or directory `path` resolves its includes under, without --glsl-root: the
// library's glsl/ for a path inside it; else the directory itself, or the file's directory (its
// parent for a pass under `passes/`): a user's copy of the modules is its own root. Throws Error
// when `path` does not exist.
std::filesystem::path root_for(const std::filesystem::path& path, const GlobalOptions& global);
std::optional<Backend> chosen_backend(const GlobalOptions& global);  // throws Error for an unknown name
Api chosen_api(const GlobalOptions& global);                        // likewise; default gl450
// Adds `--api gl450|es310` to a command that makes a context.
void add_api_option(CLI::App& command, GlobalOptions& global);

// `--register-shift t=N,s=N,u=N,b=N` and `--register-space N` (shader/register_plan.h), for `bundle
// --target hlsl` and `check --api hlsl`; `where` says that in the help.
struct RegisterPlanOptions {
  std::string shift;
  std::optional<long long> space;
  bool given() const { return !shift.empty() || space.has_value(); }
};
void add_register_plan_options(CLI::App& command, RegisterPlanOptions& options, const std::string& where);
// The plan; throws Error naming the option when `applies` is false (`what`: where they apply) or a value is wrong.
RegisterPlan register_plan_of(const RegisterPlanOptions& options, bool applies, const std::string& what);

}  // namespace pn::cli
