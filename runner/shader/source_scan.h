// Reading shader text as the compiler's tokens lie in it: identifiers, comments and directives,
// brackets. What the loop guard and the loop census (shader/loop_guard.h, shader/loop_census.h)
// share; both read glslang's preprocessed text.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "shader/target.h"

namespace pn {

bool identifier_char(char c);
// The index just past the identifier that starts at `i` (`i` when none does).
std::size_t identifier_end(const std::string& s, std::size_t i);
bool loop_keyword(const std::string& word);  // for, while, do

// A loop of a shader's source: where its keyword is (ShaderSource::origin_of_line).
struct SourceLoop {
  std::string file;
  int line = 0;
};

// The module file and line of position `at` in the flattened source (ShaderSource::origin_of_line).
std::pair<std::string, int> origin_of(const ShaderSource& source, std::size_t at);

// The index just past the directive (`#` first on its line: the preprocessor leaves #version,
// #extension, #pragma and #line) or comment starting at `i`, or `i` when none starts there. A
// directive may stand between a loop keyword and its `(` (`while⏎#line 500⏎(…)`, issue 39).
std::size_t skip_comment(const std::string& s, std::size_t i);
// The index of the first character at or after `i` that is no space, comment or directive.
std::size_t skip_space(const std::string& s, std::size_t i);

// For the bracket at `open` ('(' or '{'): the index of the one that closes it, and of each
// ';' at its own depth inside it (a for header's two).
struct Bracketed {
  std::size_t close = std::string::npos;
  std::vector<std::size_t> semicolons;
};
Bracketed match_bracket(const std::string& s, std::size_t open);

}  // namespace pn
