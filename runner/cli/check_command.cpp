#include <algorithm>
#include <filesystem>
#include <iostream>
#include <set>
#include <string>

#include "check/report.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/format.h"
#include "gl/context.h"
#include "modules/blur_face.h"
#include "vk/hlsl_root.h"
#include "vk/vulkan_device.h"

namespace pn::cli {

namespace {

// --api vulkan | hlsl: the query-pass checks on a Vulkan device (vk/vulkan_device.h); null for the
// GL APIs. Throws Error naming every API the command takes (`check`: hlsl too) for any other name.
std::optional<PassLanguage> vulkan_language(const GlobalOptions& global, bool with_hlsl) {
  if (global.api == "vulkan") return PassLanguage::glsl;
  if (global.api == "hlsl" && with_hlsl) return PassLanguage::hlsl;
  if (!global.api.empty() && global.api != api_name(Api::gl450) && global.api != api_name(Api::es310))
    throw Error("API '" + global.api + "': expected one of gl450, es310, vulkan" + (with_hlsl ? ", hlsl" : ""));
  return std::nullopt;
}

void print_vulkan_device(const VulkanDevice& device, const RegisterPlan& plan) {
  std::cout << (device.query_api() == "hlsl" ? "hlsl (each pass's HLSL export, registers " + plan.describe() +
                                                   ", compiled back by glslang) on vulkan: "
                                             : std::string("vulkan: "))
            << device.device_name() << " (" << device.device_type() << ", Vulkan "
            << device.api_version() << ", " << device.driver() << "), validation " << device.validation() << "\n";
}

}  // namespace

void add_check_command(CLI::App& app, GlobalOptions& global, int& exit_code) {
  struct Options {
    std::vector<std::string> modules;
    std::optional<int> blur_radius;
    std::optional<double> blur_sigma, blur_depth_tolerance;
    bool blur_depth_aware = false;
    bool every_case = false;
    bool quick = false;
    bool no_validation = false;
    std::string hlsl_root;
    RegisterPlanOptions registers;
    DispatchBounds bounds{true};
  };
  auto opt = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("check", "Run module checks on the GPU against CPU references");
  cmd->add_option("modules", opt->modules, "Modules to check (default: all)");
  cmd->add_option("--glsl-root", global.glsl_root, "Check the modules in this directory (a copy of glsl/)");
  cmd->add_option("--backend", global.backend, "egl-device | egl-surfaceless | osmesa (default: first that works)");
  cmd->add_option("--api", global.api,
                  "gl450 (OpenGL 4.5 core, the default) | es310 (OpenGL ES 3.1 on EGL) | vulkan (the query-pass "
                  "checks on a Vulkan device, from the vulkan target's SPIR-V) | hlsl (the same from each pass's HLSL "
                  "export, compiled back by glslang)");
  cmd->add_option("--hlsl-root", opt->hlsl_root,
                  "With --api hlsl: a directory of HLSL exports run instead of the generated ones: X.hlsl (as `bundle "
                  "X.glsl --target hlsl` writes it) for the export entry exports/X.comp or the pass passes/X.comp; "
                  "each check says which copies it ran");
  cmd->add_flag("--no-validation", opt->no_validation, "With --api vulkan | hlsl: without the Khronos validation layer");
  add_register_plan_options(*cmd, opt->registers,
                            "With --api hlsl: each export written with your plan (as `bundle` writes it) and bound there");
  cmd->add_option("--blur-radius", opt->blur_radius,
                  "Check blur with this radius only (0 to " + std::to_string(kBlurMaxRadius) + ")");
  cmd->add_option("--blur-sigma", opt->blur_sigma, "Check blur with this sigma only (texels, > 0)");
  cmd->add_flag("--blur-depth-aware", opt->blur_depth_aware, "Check the depth-aware blur only");
  cmd->add_flag("-v,--every-case", opt->every_case, "List every case with its worst element, passing ones too");
  cmd->add_flag("--quick", opt->quick,
                "Each check on one scene (tall_blocker) and three texture fixtures (step_edge, nonfinite, boxes), not all, "
                "and none of the large-data cases (pipeline's and pcss_regions' 512² screens, savsm's 1024² map, summed_area's 1024² "
                "and 2048² tables, depth_cache's sequence at K = 1): every program still runs (the suite's runs on ES, "
                "Vulkan and HLSL)");
  cmd->add_option("--blur-depth-tolerance", opt->blur_depth_tolerance, "Relative depth tolerance (>= 0)");
  cmd->add_option("--gpu-timeout", opt->bounds.timeout_s,
                  "Seconds one dispatch may take before the check fails (default 60; 0.1 to 3600)");
  cmd->add_option("--loop-limit", opt->bounds.loop_iterations,
                  "Iterations one loop may run in one invocation, over all its entries (default 65000; 1 to 2^30)");
  cmd->callback([opt, &global, &exit_code] {
    CheckOptions options;
    options.quick = opt->quick;
    if (opt->blur_radius || opt->blur_sigma || opt->blur_depth_aware || opt->blur_depth_tolerance) {
      BlurParams blur;
      blur.radius = opt->blur_radius.value_or(blur.radius);
      blur.sigma = opt->blur_sigma.value_or(blur.sigma);
      blur.depth_aware = opt->blur_depth_aware || opt->blur_depth_tolerance.has_value();
      blur.depth_tolerance = opt->blur_depth_tolerance.value_or(blur.depth_tolerance);
      blur.validate();  // bad parameters are refused before a context is made
      options.blur = blur;
    }
    // A module named more than once runs once, in the order first named (issue 39 C20).
    std::vector<std::string> modules;
    std::set<std::string> named;
    for (const std::string& m : opt->modules)
      if (named.insert(m).second) modules.push_back(m);
    opt->modules = std::move(modules);
    for (const std::string& m : opt->modules) find_module_check(m);  // unknown names, likewise
    if (!(opt->bounds.timeout_s >= 0.1 && opt->bounds.timeout_s <= 3600))  // the value as given (issue 39 C21)
      throw Error("GPU timeout " + format_shortest(opt->bounds.timeout_s) + ": expected 0.1..3600 seconds");
    if (opt->bounds.loop_iterations < 1 || opt->bounds.loop_iterations > (1u << 30))
      throw Error("loop limit " + std::to_string(opt->bounds.loop_iterations) + ": expected 1..1073741824");
    const std::optional<PassLanguage> language = vulkan_language(global, true);
    if (!opt->hlsl_root.empty() && language != PassLanguage::hlsl)
      throw Error("--hlsl-root " + opt->hlsl_root + ": applies to --api hlsl only");
    if (language && !global.backend.empty())
      throw Error("--backend " + global.backend + ": applies to the GL APIs (gl450, es310), not to " + global.api);
    if (!language && opt->no_validation) throw Error("--no-validation: applies to --api vulkan | hlsl only");
    const RegisterPlan plan = register_plan_of(opt->registers, language == PassLanguage::hlsl, "--api hlsl");
    const SourceTree tree(glsl_root_or_default(global));
    // A root that supplies no copy, or a copy named so that it would never be read, is refused
    // here, before any work (vk/hlsl_root.h); each check then says what it ran.
    const std::vector<std::string> copies =
        opt->hlsl_root.empty() ? std::vector<std::string>() : usable_hlsl_copies(opt->hlsl_root, tree);
    std::vector<ModuleReport> reports;
    std::vector<std::string> unread;  // copies no check read
    if (language) {
      VulkanSettings settings;
      settings.language = *language;
      settings.validation = !opt->no_validation;
      if (!opt->hlsl_root.empty()) settings.hlsl_root = opt->hlsl_root;
      settings.registers = plan;
      const auto device = create_vulkan_device(settings);
      device->set_dispatch_bounds(opt->bounds);
      print_vulkan_device(*device, plan);
      // One check at a time: each with its own budget of device time, and the origins of the
      // stages it compiled (--hlsl-root).
      const CheckEnvironment env(*device, tree, options);
      std::vector<std::string> modules = opt->modules;
      if (modules.empty())
        for (const ModuleCheck& check : module_checks()) modules.push_back(check.name);
      for (const std::string& module : modules) {
        device->start_budget();
        device->take_pass_origins();  // what ran before is not this check's
        reports.push_back(std::move(run_checks({module}, env).front()));
        reports.back().origins = device->take_pass_origins();
      }
      const std::vector<std::string> read = device->hlsl_copies_read();
      for (const std::string& c : copies)
        if (std::find(read.begin(), read.end(), c) == read.end()) unread.push_back(c);
    } else {
      const std::optional<Backend> backend = chosen_backend(global);
      const Api api = chosen_api(global);
      const auto context = create_context(backend, api);
      context->set_dispatch_bounds(opt->bounds);
      std::cout << "backend " << backend_name(context->backend()) << ": " << context->renderer()
                << (api == Api::gl450 ? "" : std::string(", ") + context->version()) << "\n";
      reports = run_checks(opt->modules, CheckEnvironment(*context, tree, options));
    }
    print_report(std::cout, reports, 10, opt->every_case);
    if (!unread.empty()) {
      std::string names;
      for (const std::string& c : unread) names += (names.empty() ? "" : ", ") + c;
      std::cout << "--hlsl-root " << opt->hlsl_root << ": not read by the checks run: " << names
                << " (no check run compiled that entry without defines)\n";
    }
    bool pass = true;
    for (const auto& r : reports) pass = pass && r.pass();
    exit_code = pass ? 0 : static_cast<int>(ExitCode::failed);
  });
}

void add_info_command(CLI::App& app, GlobalOptions& global, int& exit_code) {
  auto* cmd = app.add_subcommand("info", "Show the headless GL context: backend, vendor, renderer, version");
  cmd->add_option("--backend", global.backend, "egl-device | egl-surfaceless | osmesa (default: first that works)");
  cmd->add_option("--api", global.api,
                  "gl450 (the default) | es310: the GL context; vulkan: the Vulkan device the checks' --api vulkan uses");
  cmd->callback([&global, &exit_code] {
    if (vulkan_language(global, false)) {
      if (!global.backend.empty()) throw Error("--backend " + global.backend + ": applies to gl450 and es310, not vulkan");
      const auto device = create_vulkan_device();
      std::cout << "api:        vulkan\n"
                << "device:     " << device->device_name() << " (" << device->device_type() << ")\n"
                << "version:    Vulkan " << device->api_version() << "\n"
                << "driver:     " << device->driver() << "\n"
                << "validation: " << device->validation() << "\n";
      exit_code = 0;
      return;
    }
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
