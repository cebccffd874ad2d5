#include <iostream>

#include "cli/commands.h"
#include "core/write_file.h"
#include "modules/poisson_pcss_face.h"
#include "sampling/poisson_disk.h"
#include "sampling/poisson_disk_source.h"

namespace pn::cli {

void add_poisson_command(CLI::App& app, int& exit_code) {
  struct Options {
    int count = PN_POISSON_PCF_SAMPLES;
    std::uint32_t seed = 1;
    std::string name = "PN_POISSON_DISK", output, lang = "glsl";
  };
  auto opt = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("poisson", "Poisson-disk samples (Bridson) in the unit disk as a constant array in GLSL, HLSL, MSL or C++");
  cmd->add_option("--count", opt->count,
                  "Number of samples, 1 to 4096 (default 64; PCSS uses 36 for the blocker search). poisson_pcss.glsl "
                  "takes any count as a constant disk read in place (PN_POISSON_DISK_ARRAY), at most PN_POISSON_MAX_SAMPLES "
                  "(64) as a parameter array");
  cmd->add_option("--seed", opt->seed, "Seed (default 1)");
  cmd->add_option("--name", opt->name, "The constant's name (default PN_POISSON_DISK)");
  cmd->add_option("--lang", opt->lang,
                  "glsl (default: const vec2 NAME[n]), hlsl (static const float2), msl (constant float2) or cpp "
                  "(constexpr float NAME[n][2]): the disk for poisson_pcss.glsl's PN_POISSON_DISK_ARRAY, an export's "
                  "disk parameter, or a host buffer");
  cmd->add_option("-o,--output", opt->output, "Output file (default: standard output)");
  cmd->callback([opt, &exit_code] {
    const SourceLanguage language = parse_source_language(opt->lang);
    const std::string text = poisson_disk_source(poisson_disk(opt->count, opt->seed), opt->name, opt->seed, language);
    if (opt->output.empty()) std::cout << text;
    else write_file_atomically(opt->output, text);
    exit_code = 0;
  });
}

}  // namespace pn::cli
