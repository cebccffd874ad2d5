#include <ctime>
#include <iostream>

#include "bench/pyramid_bench.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/write_file.h"

namespace pn::cli {

void add_bench_command(CLI::App& app, GlobalOptions& global, int& exit_code) {
  struct Options {
    std::string what;
    std::vector<int> sizes{512, 1024, 2048};
    int repeats = 15;
    int max_level = 31;
    std::string json;
  };
  auto opt = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("bench", "GPU timings (timestamp queries, medians) against baselines in the same run");
  cmd->add_option("what", opt->what, "pyramid")->required();
  cmd->add_option("--sizes", opt->sizes, "Shadow-map sizes N (default 512 1024 2048)")->delimiter(',');
  cmd->add_option("--repeats", opt->repeats, "Timed runs per size (default 15)");
  cmd->add_option("--max-level", opt->max_level, "Pyramid maximum level (default: all)");
  cmd->add_option("--json", opt->json, "Also write the results as JSON to this file");
  cmd->add_option("--glsl-root", global.glsl_root, "Benchmark the modules in this directory");
  cmd->add_option("--backend", global.backend, "egl-device | egl-surfaceless | osmesa (default: first that works)");
  cmd->callback([opt, &global, &exit_code] {
    if (opt->what != "pyramid") throw Error("bench '" + opt->what + "': expected one of pyramid");
    const SourceTree tree(glsl_root_or_default(global));
    const auto context = create_context(chosen_backend(global));
    std::cout << "backend " << backend_name(context->backend()) << ": " << context->renderer() << ", "
              << context->version() << "\n";
    const auto rows = bench_pyramid(*context, tree, opt->sizes, opt->repeats, opt->max_level);
    print_pyramid_bench(std::cout, rows);
    if (!opt->json.empty()) {
      const std::time_t now = std::time(nullptr);
      char date[32];
      std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
      const nlohmann::json doc{{"bench", "pyramid"},
                               {"date", date},
                               {"backend", backend_name(context->backend())},
                               {"vendor", context->vendor()},
                               {"renderer", context->renderer()},
                               {"gl_version", context->version()},
                               {"results", pyramid_bench_json(rows)}};
      write_file_atomically(opt->json, doc.dump(2) + "\n");
    }
    exit_code = 0;
  });
}

}  // namespace pn::cli
