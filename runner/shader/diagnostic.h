// A compiler message mapped back to the file and line it is about.
#pragma once

#include <functional>
#include <string>
#include <utility>
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

// Maps a log location (source-string number, line) to (file, line).
using LocationMap = std::function<std::pair<std::string, int>(int string_number, int line)>;

// Parses a glslang, Mesa or NVIDIA info log and maps each location through
// `map`. Messages without a location go to `fallback_file`. Everything after
// glslang's "compilation terminated" is dropped: it is noise such as
// "missing #endif" from the aborted parse.
std::vector<Diagnostic> parse_info_log(const std::string& log, const LocationMap& map,
                                       const std::string& fallback_file);

}  // namespace pn
