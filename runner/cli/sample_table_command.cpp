#include <iostream>

#include "cli/commands.h"
#include "core/write_file.h"
#include "sampling/sample_table_generator.h"

namespace pn::cli {

void add_sample_table_command(CLI::App& app, int& exit_code) {
  struct Options {
    std::uint32_t seed = kSampleTableSeed;
    std::string output;
  };
  auto opt = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "sample-table", "Fast PCSS's 21x8 multi-jittered sample table as C float data, for an engine's RG32F texture");
  cmd->add_option("--seed", opt->seed, "Seed (default: the runner's own table, which the checks and scores use)");
  cmd->add_option("-o,--output", opt->output, "Output file (default: standard output)");
  cmd->callback([opt, &exit_code] {
    const std::string text = sample_table_text(generate_sample_table(opt->seed), opt->seed);
    if (opt->output.empty()) std::cout << text;
    else write_file_atomically(opt->output, text);
    exit_code = 0;
  });
}

}  // namespace pn::cli
