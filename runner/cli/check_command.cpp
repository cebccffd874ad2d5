#include <iostream>
#include <string>

#include "check/report.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/format.h"
#include "gl/context.h"
#include "modules/blur.h"

namespace pn::cli {

void add_check_command(CLI::App& app, GlobalOptions& global, int& exit_code) {
  struct Options {
    std::vector<std::string> modules;
    std::optional<int> blur_radius;
    std::optional<double> blur_sigma, blur_depth_tolerance;
    bool blur_depth_aware = false;
    bool every_case = false;
    DispatchBounds bounds{true};
  };
  auto opt = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("check", "Run module checks on the GPU against CPU references");
  cmd->add_option("modules", opt->modules, "Modules to check (default: all)");
  cmd->add_option("--glsl-root", global.glsl_root, "Check the modules in this directory (a copy of glsl/)");
  cmd->add_option("--backend", global.backend, "egl-device | egl-surfaceless | osmesa (default: first that works)");
  add_api_option(*cmd, global);
  cmd->add_option("--blur-radius", opt->blur_radius,
                  "Check blur with this radius only (0 to " + std::to_string(kBlurMaxRadius) + ")");
  cmd->add_option("--blur-sigma", opt->blur_sigma, "Check blur with this sigma only (texels, > 0)");
  cmd->add_flag("--blur-depth-aware", opt->blur_depth_aware, "Check the depth-aware blur only");
  cmd->add_flag("-v,--every-case", opt->every_case, "List every case with its worst element, passing ones too");
  cmd->add_option("--blur-depth-tolerance", opt->blur_depth_tolerance, "Relative depth tolerance (>= 0)");
  cmd->add_option("--gpu-timeout", opt->bounds.timeout_s,
                  "Seconds one dispatch may take before the check fails (default 60; 0.1 to 3600)");
  cmd->add_option("--loop-limit", opt->bounds.loop_iterations,
                  "Iterations one loop may run in one invocation, over all its entries (default 65000; 1 to 2^30)");
  cmd->callback([opt, &global, &exit_code] {
    CheckOptions options;
    if (opt->blur_radius || opt->blur_sigma || opt->blur_depth_aware || opt->blur_depth_tolerance) {
      BlurParams blur;
      blur.radius = opt->blur_radius.value_or(blur.radius);
      blur.sigma = opt->blur_sigma.value_or(blur.sigma);
      blur.depth_aware = opt->blur_depth_aware || opt->blur_depth_tolerance.has_value();
      blur.depth_tolerance = opt->blur_depth_tolerance.value_or(blur.depth_tolerance);
      blur.validate();  // bad parameters are refused before a context is made
      options.blur = blur;
    }
    for (const std::string& m : opt->modules) find_module_check(m);  // unknown names, likewise
    if (!(opt->bounds.timeout_s >= 0.1 && opt->bounds.timeout_s <= 3600))
      throw Error("GPU timeout " + format_number("%g", opt->bounds.timeout_s) + ": expected 0.1..3600 seconds");
    if (opt->bounds.loop_iterations < 1 || opt->bounds.loop_iterations > (1u << 30))
      throw Error("loop limit " + std::to_string(opt->bounds.loop_iterations) + ": expected 1..1073741824");
    const SourceTree tree(glsl_root_or_default(global));
    const std::optional<Backend> backend = chosen_backend(global);
    const Api api = chosen_api(global);
    const auto context = create_context(backend, api);
    context->set_dispatch_bounds(opt->bounds);
    std::cout << "backend " << backend_name(context->backend()) << ": " << context->renderer()
              << (api == Api::gl450 ? "" : std::string(", ") + context->version()) << "\n";
    const CheckEnvironment env{*context, tree, options};
    const auto reports = run_checks(opt->modules, env);
    print_report(std::cout, reports, 10, opt->every_case);
    bool pass = true;
    for (const auto& r : reports) pass = pass && r.pass();
    exit_code = pass ? 0 : static_cast<int>(ExitCode::failed);
  });
}

void add_info_command(CLI::App& app, GlobalOptions& global, int& exit_code) {
  auto* cmd = app.add_subcommand("info", "Show the headless GL context: backend, vendor, renderer, version");
  cmd->add_option("--backend", global.backend, "egl-device | egl-surfaceless | osmesa (default: first that works)");
  add_api_option(*cmd, global);
  cmd->callback([&global, &exit_code] {
    const auto context = create_context(chosen_backend(global), chosen_api(global));
    std::cout << "backend:  " << backend_name(context->backend()) << "\n"
              << "api:      " << api_name(context->api()) << " (" << api_title(context->api()) << ")\n"
              << "vendor:   " << context->vendor() << "\n"
              << "renderer: " << context->renderer() << "\n"
              << "version:  " << context->version() << "\n";
    std::string features;
    for (const auto& [has, what] : {std::pair{context->has_timer_queries(), "timer queries"},
                                    {context->has_texture_views(), "texture views"},
                                    {context->has_debug_output(), "debug output"}})
      features += std::string(features.empty() ? "" : ", ") + what + (has ? "" : " (none)");
    std::cout << "features: " << features << "\n";
    std::string compiled;
    for (Backend b : compiled_backends()) compiled += std::string(compiled.empty() ? "" : ", ") + backend_name(b);
    std::cout << "backends in this build: " << compiled << "\n";
    exit_code = 0;
  });
}

}  // namespace pn::cli
