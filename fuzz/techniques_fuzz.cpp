// Fuzz target: the technique parser behind `--techniques` (render and
// bench): the comma-separated list that CLI11 splits, each technique
// "name[:key=value]..." through parse_technique (technique/technique_registry)
// and set_pcss_setting / PcssSettings::validate (pipeline/pcss_settings).
//
// Input: the option's value, e.g. "exact,fast:leaf=4:refine=3". A pn::Error
// (exit 2, one line) is the expected answer to a bad technique.
#include <cstdlib>
#include <memory>
#include <string>

#include "core/error.h"
#include "fuzz_input.h"
#include "technique/technique_registry.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string value = pn::fuzz::as_text(data, size);
  size_t begin = 0;
  while (begin <= value.size()) {
    size_t end = value.find(',', begin);
    if (end == std::string::npos) end = value.size();
    const std::string technique = value.substr(begin, end - begin);
    try {
      const std::unique_ptr<pn::TechniqueConfig> config = pn::parse_technique(technique);
      // What render and bench do with an accepted technique before any GL: its name, a copy, its keys.
      if (config->name() != technique) std::abort();
      const std::unique_ptr<pn::TechniqueConfig> copy = config->clone();
      copy->validate();
      (void)copy->keys();
    } catch (const pn::Error& e) {
      if (std::string(e.what()).empty()) std::abort();  // an error names the technique
    }
    begin = end + 1;
  }
  return 0;
}
