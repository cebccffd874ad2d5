#include <algorithm>
#include <iostream>

#include "cli/commands.h"
#include "core/error.h"
#include "core/write_file.h"
#include "isa/isa_budget.h"
#include "isa/isa_entries.h"
#include "isa/isa_report.h"
#include "isa/isa_run.h"

namespace pn::cli {

void add_isa_command(CLI::App& app, GlobalOptions& global, int& exit_code) {
  struct Options {
    std::vector<std::string> families{"polaris10", "vega10", "navi10", "navi21", "gfx1100"};
    std::vector<int> waves{64, 32};
    std::vector<std::string> kinds{"engine", "runner", "pass"};
    std::vector<std::string> only;
    std::string json;
    std::string isa_dir;
    bool budgets = false;
    int jobs = 2;
  };
  auto opt = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "isa", "What AMD's compiler (ACO, Mesa's RADV on a null device: no GPU needed) makes of each call and pass");
  cmd->add_option("--families", opt->families, "RADV chip families (default polaris10,vega10,navi10,navi21,gfx1100)")->delimiter(',');
  cmd->add_option("--waves", opt->waves, "Wave sizes (default 64,32; 32 on gfx10 and later only)")->delimiter(',');
  cmd->add_option("--kinds", opt->kinds, "engine (each call as an engine compiles it), runner (each technique's pass as the runner runs it), pass (every pass and export as written); default all")->delimiter(',');
  cmd->add_option("--only", opt->only, "Only the entries of these names (fast_pcss, fast, passes/blur.comp, …)")->delimiter(',');
  cmd->add_option("--json", opt->json, "Also write every figure and statistic as JSON to this file");
  cmd->add_option("--isa", opt->isa_dir, "Also write each shader's ISA under this directory (<family>-wave<N>/<entry>.s)");
  cmd->add_flag("--budgets", opt->budgets, "Fail (exit 1) when a call is over the budget in its module's header or any entry uses scratch (needs navi21 wave64)");
  cmd->add_option("--jobs", opt->jobs, "Targets compiled at once (default 2)")->check(CLI::Range(1, 64));
  cmd->add_option("--glsl-root", global.glsl_root, "The modules to compile (default: the library's)");
  cmd->callback([opt, &global, &exit_code] {
    std::vector<RadvTarget> targets;
    for (const std::string& family : opt->families) {
      if (family.empty() || family.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") != std::string::npos)
        throw Error("--families '" + family + "': expected RADV chip names such as polaris10, vega10, navi10, navi21, gfx1100");
      for (int wave : opt->waves) {
        if (wave != 32 && wave != 64) throw Error("--waves " + std::to_string(wave) + ": expected 32 or 64");
        if (supports_wave(family, wave)) targets.push_back({family, wave});
      }
    }
    if (targets.empty()) throw Error("--families/--waves: no target to compile for");
    std::vector<IsaKind> kinds;
    for (const std::string& k : opt->kinds) kinds.push_back(parse_isa_kind(k));
    const bool budget_target = std::any_of(targets.begin(), targets.end(), [](const RadvTarget& t) {
      return t.family == kBudgetFamily && t.wave == kBudgetWave;
    });
    if (opt->budgets && !budget_target)
      throw Error(std::string("--budgets: the budgets are for ") + kBudgetFamily + " wave" + std::to_string(kBudgetWave) +
                  ": add it to --families and --waves");
    if (!opt->json.empty()) probe_output_file(opt->json);
    // --isa's directory made and written to before the work, or refused in one line (issue 54 X4:
    // /proc/self/x failed after every compile); made but left empty by a failed run, removed again.
    MadeDirectories made(opt->isa_dir.empty() ? std::vector<std::filesystem::path>{}
                                              : prepare_output_directory(opt->isa_dir, {kIsaManifestName}));

    const SourceTree tree(glsl_root_or_default(global));
    std::vector<IsaEntry> entries;
    for (const IsaEntry& e : isa_entries(tree)) {
      if (std::find(kinds.begin(), kinds.end(), e.kind) == kinds.end()) continue;
      if (!opt->only.empty() && std::find(opt->only.begin(), opt->only.end(), e.name) == opt->only.end()) continue;
      entries.push_back(e);
    }
    for (const std::string& name : opt->only)
      if (std::none_of(entries.begin(), entries.end(), [&](const IsaEntry& e) { return e.name == name; }))
        throw Error("--only '" + name + "': no entry of that name among the kinds asked for");
    const IsaBudgets budgets = opt->budgets ? read_budgets(tree, entries) : IsaBudgets{};
    require_radv_families(opt->families, opt->jobs);  // a device a family, before any compiling
    const GlslangProcess glslang;
    const std::vector<IsaProgram> programs = compile_isa_programs(glslang, tree, entries);
    std::cerr << "isa: " << programs.size() << " shaders on " << targets.size() << " targets\n";
    const std::vector<IsaTargetResult> results =
        run_isa(programs, targets, opt->jobs, [](const std::string& line) { std::cerr << "isa: " << line << "\n"; });

    int failed = 0;
    for (const IsaTargetResult& r : results) {
      std::cout << isa_table(programs, r) << "\n";
      if (!r.error.empty()) ++failed;
    }
    if (!opt->json.empty()) write_file_atomically(opt->json, isa_json(programs, results).dump(1) + "\n");
    if (!opt->isa_dir.empty()) write_isa_files(opt->isa_dir, programs, results);
    made.keep();
    if (opt->budgets) {
      for (const IsaTargetResult& r : results) {
        if (r.target.family != kBudgetFamily || r.target.wave != kBudgetWave) continue;
        const std::vector<std::string> breaches = budget_breaches(budgets, programs, r);
        for (const std::string& b : breaches) std::cout << "isa: over budget: " << b << "\n";
        std::cout << "isa: budgets (" << kBudgetFamily << " wave" << kBudgetWave << "): "
                  << (breaches.empty() ? "every entry within" : std::to_string(breaches.size()) + " breaches") << "\n";
        if (!breaches.empty()) ++failed;
      }
    }
    exit_code = failed == 0 ? 0 : static_cast<int>(ExitCode::failed);
  });
}

}  // namespace pn::cli
