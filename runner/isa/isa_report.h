// `penumbra isa`'s output: a Markdown table a target, the JSON of every figure and statistic, and
// the ISA text a shader under a directory.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "isa/isa_run.h"

namespace pn {

std::string isa_table(const std::vector<IsaProgram>& programs, const IsaTargetResult& result);
nlohmann::json isa_json(const std::vector<IsaProgram>& programs, const std::vector<IsaTargetResult>& results);
// DIR/<family>-wave<N>/<entry>.s (the entry's label, '/' and ' ' as '_'), one a shader compiled,
// and last the set's manifest DIR/isa_manifest.txt (`HASH  <family>-wave<N>/<entry>.s` a file,
// FNV-1a 64), removed before the first file: the files of an earlier run with other entries or
// another root stay beside these, and only the manifest says which set is this run's, whole
// (issue 54 X5, as render's manifest does).
inline constexpr const char* kIsaManifestName = "isa_manifest.txt";
void write_isa_files(const std::filesystem::path& dir, const std::vector<IsaProgram>& programs,
                     const std::vector<IsaTargetResult>& results);

}  // namespace pn
