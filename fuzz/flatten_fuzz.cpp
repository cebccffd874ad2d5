// Fuzz target: the include resolver and the flattener (shader/source_tree,
// shader/flatten) and the standalone wrapper after them (shader/target), as
// `penumbra lint` and `penumbra bundle` run them.
//
// Input: up to six GLSL files separated by lines that are exactly "//---",
// written to a scratch glsl root as m.glsl (the entry), a.glsl, b.glsl,
// passes/p.comp, passes/a.glsl and sub/c.vert; their `#include` lines name
// each other, missing files, directories, "..", absolute paths — anything.
// A pn::Error is the expected answer to bad input; any other exception, a
// crash, a leak, a hang or a broken promise of flatten.h or source_tree.h
// (checked below) is a finding.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "fuzz_input.h"
#include "shader/flatten.h"
#include "shader/target.h"

namespace {

const char* const kFiles[] = {"m.glsl", "a.glsl", "b.glsl", "passes/p.comp", "passes/a.glsl", "sub/c.vert"};
constexpr size_t kMaxFiles = sizeof kFiles / sizeof kFiles[0];

void check(bool promise) {
  if (!promise) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const pn::fuzz::ScratchDir scratch("flatten");
  scratch.clear();
  const std::vector<std::string> parts = pn::fuzz::split_parts(pn::fuzz::as_text(data, size), "//---", kMaxFiles);
  for (size_t i = 0; i < parts.size(); ++i) scratch.write(kFiles[i], parts[i]);

  try {
    const pn::SourceTree tree(scratch.path());
    const pn::FlatSource flat = pn::flatten(tree, scratch.path() / kFiles[0]);
    // flatten.h: each file appears once, the entry first.
    check(!flat.files.empty() && flat.files.front() == kFiles[0]);
    check(std::set<std::string>(flat.files.begin(), flat.files.end()).size() == flat.files.size());
    // source_tree.h: what is included is a GLSL file inside the root, not a directory.
    for (const std::string& file : flat.files) check(std::filesystem::is_regular_file(scratch.path() / file));
    (void)flat.file_table_comment();
    for (pn::Target target : pn::all_targets()) {
      const pn::ShaderSource source = pn::standalone_source(flat, target, {{"PN_FUZZ", "1"}});
      const std::string driver = source.driver_text();
      // A few physical lines mapped back, as a driver's log would ask (every line would be quadratic).
      const int lines = static_cast<int>(std::count(driver.begin(), driver.end(), '\n'));
      for (int line : {0, 1, lines / 2, lines, lines + 1}) {
        const auto [file, at] = source.origin_of_line(line);
        check(!file.empty());
      }
    }
  } catch (const pn::Error&) {
    // refused with a message: the expected answer to bad input
  }
  return 0;
}
