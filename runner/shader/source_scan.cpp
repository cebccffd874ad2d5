#include "shader/source_scan.h"

#include <algorithm>
#include <cctype>

namespace pn {

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

size_t identifier_end(const std::string& s, size_t i) {
  while (i < s.size() && identifier_char(s[i])) ++i;
  return i;
}

bool loop_keyword(const std::string& word) { return word == "for" || word == "while" || word == "do"; }

std::pair<std::string, int> origin_of(const ShaderSource& source, size_t at) {
  const std::string& s = source.text;
  return source.origin_of_line(static_cast<int>(std::count(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(at), '\n')) + 1);
}

size_t skip_comment(const std::string& s, size_t i) {
  if (s[i] == '#') {
    size_t b = i;
    while (b > 0 && (s[b - 1] == ' ' || s[b - 1] == '\t')) --b;
    if (b == 0 || s[b - 1] == '\n') {
      const size_t end = s.find('\n', i);
      return end == std::string::npos ? s.size() : end;
    }
  }
  if (s.compare(i, 2, "//") == 0) {
    const size_t end = s.find('\n', i);
    return end == std::string::npos ? s.size() : end;
  }
  if (s.compare(i, 2, "/*") == 0) {
    const size_t end = s.find("*/", i + 2);
    return end == std::string::npos ? s.size() : end + 2;
  }
  return i;
}

size_t skip_space(const std::string& s, size_t i) {
  while (i < s.size()) {
    if (std::isspace(static_cast<unsigned char>(s[i])) != 0) ++i;
    else if (const size_t after = skip_comment(s, i); after != i) i = after;
    else break;
  }
  return i;
}

Bracketed match_bracket(const std::string& s, size_t open) {
  const char opening = s[open], closing = opening == '(' ? ')' : '}';
  Bracketed b;
  int depth = 0;
  for (size_t i = open; i < s.size();) {
    if (const size_t after = skip_comment(s, i); after != i) {
      i = after;
      continue;
    }
    if (s[i] == opening) ++depth;
    else if (s[i] == closing && --depth == 0) {
      b.close = i;
      return b;
    } else if (s[i] == ';' && depth == 1) b.semicolons.push_back(i);
    ++i;
  }
  return b;
}

}  // namespace pn
