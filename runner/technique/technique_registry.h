// Every technique and ablation, found by name: one entry each, which also says where it runs
// by default. The files a new technique takes: docs/architecture.md, "Adding a technique".
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "frame/technique.h"

namespace pn {

// One entry a technique or ablation. Where it shows up by default is part of the entry, so a new
// technique left at these defaults is in render's sheet, bench's lists, the frontier, the
// techniques figure and `penumbra techniques` (docs/cli.md's table) with no other line to write.
struct TechniqueEntry {
  const char* name;
  const char* summary;
  std::unique_ptr<TechniqueConfig> (*make)();  // the entry's settings, named `name`
  const char* family = nullptr;  // the technique it varies (frontier's colour and grouping); null: itself
  bool rendered = true;          // in render's and bench sweep's default sheet, and the techniques figure
  bool benched = true;  // in bench pipeline's default list (false: a check's construct, equal to another by design)
  // Its points on bench frontier's default list: "" the entry itself, ":key=value…" a variant; none: {}.
  std::vector<const char*> frontier = {""};

  std::string family_name() const { return family ? family : name; }
};

// In the order of every table.
const std::vector<TechniqueEntry>& technique_registry();

// The family of a technique's entry (TechniqueEntry::family_name). Throws Error for a name no entry has.
std::string technique_family(const std::string& technique);

// A technique as the command line names it, "name" or "name:key=value:key=value" (keys: the
// entry's own), parsed into its TechniqueConfig (whose name() it stays) and validated.
// Throws Error naming the technique: an unknown name (listing the known ones), a
// malformed item, an unknown key or a value out of range.
std::unique_ptr<TechniqueConfig> parse_technique(const std::string& technique);

// The techniques a command runs: `chosen` when the user gave any, else `defaults` parsed into
// `parsed`, which owns them for as long as the returned pointers are used.
std::vector<const TechniqueConfig*> chosen_or_default_techniques(
    const std::vector<std::shared_ptr<const TechniqueConfig>>& chosen, const std::vector<std::string>& defaults,
    std::vector<std::unique_ptr<TechniqueConfig>>& parsed);

// The default lists, from the entries (registry order): what render draws, what bench
// pipeline times, and bench frontier's points.
std::vector<std::string> render_techniques();
std::vector<std::string> bench_techniques();
std::vector<std::string> frontier_techniques();

// The techniques scores and speed-ups are measured against (same run).
inline constexpr const char* kExactTechnique = "exact";
inline constexpr const char* kPoissonTechnique = "poisson";
// Poisson PCSS through the staged passes: the baseline the bench timed before issue 24.
inline constexpr const char* kStagedPoissonTechnique = "poisson-staged";

}  // namespace pn
