#include "shader/diagnostic.h"

#include <cctype>
#include <initializer_list>
#include <sstream>
#include <string_view>

#include "core/decimal.h"

namespace pn {

std::string Diagnostic::str() const {
  std::string out = file;
  if (line > 0) out += ":" + std::to_string(line);
  return out + ": " + severity + ": " + message;
}

namespace {

// The log formats are scanned by hand, not with std::regex: libstdc++'s regex
// recurses per character and overflowed the stack on a 60,000-character log
// line (fuzz_diagnostic, docs/reliability.md "Fuzzing"). Each scan matches
// what the regex it replaced matched, `.` excluding '\r' included.
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }

// A cursor over one line of the log.
class Scan {
 public:
  explicit Scan(const std::string& line) : s_(line) {}

  bool literal(std::string_view word) {
    if (s_.compare(i_, word.size(), word) != 0) return false;
    i_ += word.size();
    return true;
  }
  // One of `words`, copied to `out`.
  bool one_of(std::initializer_list<std::string_view> words, std::string& out) {
    for (std::string_view w : words)
      if (literal(w)) return out = w, true;
    return false;
  }
  // `\d+`
  bool digits(std::string& out) {
    const size_t begin = i_;
    while (i_ < s_.size() && is_digit(s_[i_])) ++i_;
    out = s_.substr(begin, i_ - begin);
    return i_ > begin;
  }
  // `\w*`
  void word() {
    while (i_ < s_.size() && is_word(s_[i_])) ++i_;
  }
  // `(.*?)\s*$`: the rest of the line without its trailing white space, which
  // must hold no '\r' (the regexes' `.` matched none).
  bool message(std::string& out) {
    size_t end = s_.size();
    while (end > i_ && is_space(s_[end - 1])) --end;
    if (s_.find('\r', i_) < end) return false;
    out = s_.substr(i_, end - i_);
    return true;
  }
  // `.*$`
  bool rest() const { return s_.find('\r', i_) == std::string::npos; }

 private:
  const std::string& s_;
  size_t i_ = 0;
};

struct Located {
  std::string number, line, severity, message;
};

// glslang: "ERROR: 2:14: 'x' : undeclared identifier"
bool glslang_line(const std::string& line, Located& out) {
  Scan s(line);
  return s.one_of({"ERROR", "WARNING"}, out.severity) && s.literal(": ") && s.digits(out.number) &&
         s.literal(":") && s.digits(out.line) && s.literal(": ") && s.message(out.message);
}

// Mesa: "0:14(3): error: `x' undeclared"
bool mesa_line(const std::string& line, Located& out) {
  Scan s(line);
  std::string column;
  return s.digits(out.number) && s.literal(":") && s.digits(out.line) && s.literal("(") && s.digits(column) &&
         s.literal("): ") && s.one_of({"error", "warning"}, out.severity) && s.literal(": ") && s.message(out.message);
}

// NVIDIA: "0(14) : error C1008: undefined variable "x""
bool nvidia_line(const std::string& line, Located& out) {
  Scan s(line);
  if (!(s.digits(out.number) && s.literal("(") && s.digits(out.line) && s.literal(") : ") &&
        s.one_of({"error", "warning"}, out.severity) && s.literal(" ")))
    return false;
  s.word();
  if (!s.literal(":")) return false;
  s.literal(" ");
  return s.message(out.message);
}

// glslang without a location: "ERROR: Linking compute stage: Missing entry point"
bool glslang_bare_line(const std::string& line, Located& out) {
  Scan s(line);
  return s.one_of({"ERROR", "WARNING"}, out.severity) && s.literal(": ") && s.message(out.message);
}

// "ERROR: 3 compilation errors.  No code generated."
bool summary_line(const std::string& line) {
  Scan s(line);
  std::string ignored;
  return s.one_of({"ERROR", "WARNING"}, ignored) && s.literal(": ") && s.digits(ignored) &&
         s.literal(" compilation ") && s.one_of({"errors", "warnings"}, ignored) && s.literal(".") && s.rest();
}

// "ERROR: 0:12: '' : compilation terminated"
bool terminated_line(const std::string& line) {
  return line.find("'' : compilation terminated") != std::string::npos && line.find('\r') == std::string::npos;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::vector<Diagnostic> parse_info_log(const std::string& log, const LocationMap& map,
                                       const std::string& fallback_file) {
  auto at = [&](const Located& l) {
    auto [file, mapped_line] = map(saturating_decimal(l.number), saturating_decimal(l.line));
    return Diagnostic{file, mapped_line, lower(l.severity), l.message};
  };

  std::vector<Diagnostic> out;
  std::istringstream lines(log);
  std::string line;
  while (std::getline(lines, line)) {
    if (terminated_line(line)) {
      // The aborted parse leaves include guards open: not the user's error.
      while (!out.empty() && out.back().message == "'' : missing #endif") out.pop_back();
      break;
    }
    if (summary_line(line)) continue;
    Located l;
    if (glslang_line(line, l) || (l = {}, mesa_line(line, l)) || (l = {}, nvidia_line(line, l))) {
      out.push_back(at(l));
    } else if ((l = {}, glslang_bare_line(line, l)) && !l.message.empty()) {
      out.push_back({fallback_file, 0, lower(l.severity), l.message});
    }
  }
  return out;
}

}  // namespace pn
