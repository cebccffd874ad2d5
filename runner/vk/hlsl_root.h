// `check --api hlsl --hlsl-root DIR`: an engine's own copies of HLSL exports, run by the checks in
// place of the generated ones. A copy is found by name: DIR/X.hlsl stands in for the compute entry
// X of the glsl root — an export entry (exports/X.comp: "pcf", "poisson_pcss", …) or a pass
// (passes/X.comp) — whenever that entry is compiled without extra defines (a copy is one fixed
// text). The names come from the glsl root itself, so an export added there is covered with no
// code here. Every check says which copies it ran and which entries it ran from the library's own
// export instead (check/report.cpp); a root that supplies nothing is refused before any work.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace pn {

class SourceTree;

// The compute entries of `tree` a copy may stand in for, by stem: every exports/X.comp and
// passes/X.comp, sorted, exports first.
std::vector<std::string> hlsl_copy_names(const SourceTree& tree);

// The files of `root` that stand in for an entry (their names, "pcf.hlsl"), sorted. Throws
// Error (usage: exit 2, one line naming the root and what was expected) when `root` is not a
// directory; when it holds no usable copy (empty, only other files, files in subdirectories);
// and when an entry of it is a mistake that would make a check fall back — a `.hlsl` named as an
// entry but in another case (`PCF.hlsl`, `pcf.HLSL`), or named as one but not a regular file
// (a dangling or looping link, a directory, a FIFO) or leaving the root through a link.
std::vector<std::string> usable_hlsl_copies(const std::filesystem::path& root, const SourceTree& tree);

}  // namespace pn
