// A compiler message mapped back to the file and line it is about.
#pragma once

#include <string>
#include <vector>

namespace pn {

struct Diagnostic {
  std::string file;  // as printed (see SourceTree::diagnostic_path)
  int line = 0;      // 0 when the message has no line
  std::string severity;  // "error" or "warning"
  std::string message;

  // "file:line: error: message" (or "file: error: message" without a line).
  std::string str() const;
};

// Parses a glslang or driver info log whose locations are "FILE_NUMBER:LINE"
// (the integer `#line` markers of a flattened source) and maps each file
// number through `files`. Messages without a location go to `fallback_file`.
std::vector<Diagnostic> parse_info_log(const std::string& log, const std::vector<std::string>& files,
                                       const std::string& fallback_file);

}  // namespace pn
