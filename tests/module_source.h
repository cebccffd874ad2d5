// A module's text as a standalone shader's source, for the tests of the rewrites that read a
// shader's loops (loop_guard_test.cpp, loop_census_test.cpp): the body is file m.glsl from line 1.
#pragma once

#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "shader/source_scan.h"
#include "shader/target.h"

namespace pn::test {

inline ShaderSource module_source(const std::string& body, Target target = Target::gl450) {
  FlatSource flat;
  flat.text = "#line 1 0\n" + body;
  flat.files = {"m.glsl"};
  flat.has_main = true;  // no entry point appended: the text ends where the module does
  return standalone_source(flat, target);
}

// The lines of `loops`, each checked to be in m.glsl.
inline std::vector<int> loop_lines(const std::vector<SourceLoop>& loops) {
  std::vector<int> lines;
  for (const SourceLoop& l : loops) {
    CHECK(l.file == "m.glsl");
    lines.push_back(l.line);
  }
  return lines;
}

}  // namespace pn::test
