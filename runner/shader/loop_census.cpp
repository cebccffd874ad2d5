#include "shader/loop_census.h"

#include <algorithm>

#include "shader/glslang_compiler.h"
#include "shader/source_scan.h"

namespace pn {
namespace {

struct Insertion {
  std::size_t at;
  std::string text;
};

std::string word_at(const std::string& s, std::size_t i) { return s.substr(i, identifier_end(s, i) - i); }

// The index just past the statement that starts at `i`: a block, a loop or branch with its
// body (and else), or a simple statement up to its ';' outside brackets.
std::size_t statement_end(const std::string& s, std::size_t i) {
  if (i >= s.size()) return s.size();
  if (s[i] == '{') {
    const std::size_t close = match_bracket(s, i).close;
    return close == std::string::npos ? s.size() : close + 1;
  }
  const std::string word = word_at(s, i);
  if (word == "for" || word == "while" || word == "if" || word == "switch") {
    const std::size_t open = skip_space(s, i + word.size());
    if (open >= s.size() || s[open] != '(') return s.size();
    const std::size_t close = match_bracket(s, open).close;
    if (close == std::string::npos) return s.size();
    if (word == "switch") return statement_end(s, skip_space(s, close + 1));
    std::size_t end = statement_end(s, skip_space(s, close + 1));
    if (word == "if") {
      const std::size_t next = skip_space(s, end);
      if (next < s.size() && word_at(s, next) == "else") end = statement_end(s, skip_space(s, next + 4));
    }
    return end;
  }
  if (word == "do") {
    const std::size_t body_end = statement_end(s, skip_space(s, i + 2));
    const std::size_t semicolon = s.find(';', body_end);  // `while (…);`
    return semicolon == std::string::npos ? s.size() : semicolon + 1;
  }
  int depth = 0;
  for (std::size_t k = i; k < s.size();) {
    if (const std::size_t after = skip_comment(s, k); after != k) {
      k = after;
      continue;
    }
    if (s[k] == '(' || s[k] == '[' || s[k] == '{') ++depth;
    else if (s[k] == ')' || s[k] == ']' || s[k] == '}') --depth;
    else if (s[k] == ';' && depth == 0) return k + 1;
    ++k;
  }
  return s.size();
}

// The buffer and the count's prototype before the source; its body after it, where the pass's
// work group size is declared (gl_WorkGroupSize needs its layout first).
std::string census_prelude(unsigned binding) {
  return "layout(std430, binding = " + std::to_string(binding) +
         ") buffer PnLoopCensus { uint pnLoopCensusCounts[]; };\n"
         "void pnLoopCensus(uint loop);\n";
}

std::string census_body(std::size_t loops) {
  return "\nvoid pnLoopCensus(uint loop) {\n"
         "  uint width = gl_NumWorkGroups.x * gl_WorkGroupSize.x;\n"
         "  uint slot = gl_GlobalInvocationID.y * width + gl_GlobalInvocationID.x;\n"
         "  pnLoopCensusCounts[slot * " + std::to_string(loops + 1) + "u + loop + 1u] += 1u;\n"
         "}\n";
}

}  // namespace

std::vector<CensusLoop> census_preprocessed_loops(ShaderSource& source, unsigned binding) {
  std::string& s = source.text;
  std::size_t start = s.compare(0, 6, "#line ") == 0 ? 0 : s.find("\n#line ");
  start = start == 0 ? 0 : start == std::string::npos ? s.size() : start + 1;

  std::vector<Insertion> edits;
  std::vector<CensusLoop> loops;
  std::vector<std::size_t> do_whiles;  // the `while` keywords that end a do-while: not loops of their own
  for (std::size_t i = start; i < s.size();) {
    if (const std::size_t after = skip_comment(s, i); after != i) {
      i = after;
      continue;
    }
    if (!identifier_char(s[i])) {
      ++i;
      continue;
    }
    const std::size_t keyword = i, end = identifier_end(s, i);
    const std::string word = s.substr(i, end - i);
    i = end;
    if (!loop_keyword(word) || std::find(do_whiles.begin(), do_whiles.end(), keyword) != do_whiles.end()) continue;
    std::size_t body = 0;
    if (word == "do") {
      body = skip_space(s, end);
      do_whiles.push_back(skip_space(s, statement_end(s, body)));
    } else {
      const std::size_t open = skip_space(s, end);
      if (open >= s.size() || s[open] != '(') continue;
      const std::size_t close = match_bracket(s, open).close;
      if (close == std::string::npos) continue;  // the compiler reports the syntax error
      body = skip_space(s, close + 1);
    }
    if (body >= s.size()) continue;
    const std::string count = " pnLoopCensus(" + std::to_string(loops.size()) + "u); ";
    if (s[body] == '{') {
      edits.push_back({body + 1, count});
    } else {
      edits.push_back({body, "{" + count});
      edits.push_back({statement_end(s, body), "}"});
    }
    const auto [file, line] = origin_of(source, keyword);
    loops.push_back({file, line});
  }
  std::stable_sort(edits.begin(), edits.end(), [](const Insertion& a, const Insertion& b) { return a.at > b.at; });
  for (const Insertion& e : edits) s.insert(e.at, e.text);
  s += census_body(loops.size());
  s.insert(start, census_prelude(binding));
  return loops;
}

std::vector<CensusLoop> census_loops(const GlslangProcess& process, ShaderSource& source, Target target,
                                     unsigned binding) {
  const Preprocessed p = preprocess_with_glslang(process, source, target);
  throw_unless_preprocessed(p);
  source.text = p.text;
  return census_preprocessed_loops(source, binding);
}

}  // namespace pn
