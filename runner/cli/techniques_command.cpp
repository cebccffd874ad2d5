// `penumbra techniques`: the registry as the commands see it — each entry, its family, where it
// runs by default and its override keys. `--markdown` prints the table docs/cli.md holds
// (the CTest cli_techniques_table compares the two), so the page lists a new entry or fails.
#include <algorithm>
#include <iostream>
#include <sstream>

#include "cli/commands.h"
#include "technique/technique_registry.h"

namespace pn::cli {
namespace {

std::string joined(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

// Where the entry runs when a command is given no technique list.
std::string defaults_of(const TechniqueEntry& e) {
  std::vector<std::string> where;
  if (e.rendered) where.push_back("render");
  if (e.benched) where.push_back("bench");
  if (!e.frontier.empty()) where.push_back("frontier (" + std::to_string(e.frontier.size()) + ")");
  return where.empty() ? "—" : joined(where, ", ");
}

std::string techniques_text(bool markdown) {
  std::ostringstream out;
  if (markdown) out << "| technique | family | by default in | override keys | what it is |\n| --- | --- | --- | --- | --- |\n";
  std::vector<std::pair<std::string, std::string>> key_sets;  // (keys, the first entry that has them)
  for (const TechniqueEntry& e : technique_registry()) {
    std::string keys = joined(e.make()->keys(), ", ");
    const auto same = std::find_if(key_sets.begin(), key_sets.end(), [&](const auto& s) { return s.first == keys; });
    if (same != key_sets.end()) keys = "as `" + same->second + "`";  // one long list once, not 20 times
    else key_sets.emplace_back(keys, e.name);
    const std::string family = e.family_name();
    if (markdown)
      out << "| `" << e.name << "` | " << family << " | " << defaults_of(e) << " | " << (keys.empty() ? "—" : keys)
          << " | " << e.summary << " |\n";
    else
      out << e.name << "\n  family " << family << "; by default in " << defaults_of(e) << "\n  keys: "
          << (keys.empty() ? "none" : keys) << "\n  " << e.summary << "\n";
  }
  return out.str();
}

}  // namespace

void add_techniques_command(CLI::App& app, int& exit_code) {
  auto markdown = std::make_shared<bool>(false);
  auto* cmd = app.add_subcommand("techniques", "List the techniques render and bench take: family, defaults, keys");
  cmd->add_flag("--markdown", *markdown, "As the table in docs/cli.md");
  cmd->callback([markdown, &exit_code] {
    std::cout << techniques_text(*markdown);
    exit_code = 0;
  });
}

}  // namespace pn::cli
