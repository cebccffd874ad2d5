#include "shader/diagnostic.h"

#include <regex>

#include "core/decimal.h"
#include <sstream>

namespace pn {

std::string Diagnostic::str() const {
  std::string out = file;
  if (line > 0) out += ":" + std::to_string(line);
  return out + ": " + severity + ": " + message;
}

std::vector<Diagnostic> parse_info_log(const std::string& log, const LocationMap& map,
                                       const std::string& fallback_file) {
  // glslang: "ERROR: 2:14: 'x' : undeclared identifier"
  // Mesa:    "0:14(3): error: `x' undeclared"
  // NVIDIA:  "0(14) : error C1008: undefined variable "x""
  static const std::regex glslang_re(R"(^(ERROR|WARNING): (\d+):(\d+): (.*?)\s*$)");
  static const std::regex glslang_bare_re(R"(^(ERROR|WARNING): (.*?)\s*$)");
  static const std::regex mesa_re(R"(^(\d+):(\d+)\(\d+\): (error|warning): (.*?)\s*$)");
  static const std::regex nvidia_re(R"(^(\d+)\((\d+)\) : (error|warning) \w*: ?(.*?)\s*$)");
  static const std::regex summary_re(R"(^(ERROR|WARNING): \d+ compilation (errors|warnings)\..*)");
  static const std::regex terminated_re(R"(.*'' : compilation terminated.*)");

  auto at = [&](const std::string& number, const std::string& line, std::string severity, std::string message) {
    auto [file, mapped_line] = map(saturating_decimal(number), saturating_decimal(line));
    return Diagnostic{file, mapped_line, std::move(severity), std::move(message)};
  };
  auto lower = [](std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };

  std::vector<Diagnostic> out;
  std::istringstream lines(log);
  std::string line;
  std::smatch m;
  while (std::getline(lines, line)) {
    if (std::regex_match(line, terminated_re)) {
      // The aborted parse leaves include guards open: not the user's error.
      while (!out.empty() && out.back().message == "'' : missing #endif") out.pop_back();
      break;
    }
    if (std::regex_match(line, summary_re)) continue;
    if (std::regex_match(line, m, glslang_re)) {
      out.push_back(at(m[2], m[3], lower(m[1]), m[4]));
    } else if (std::regex_match(line, m, mesa_re) || std::regex_match(line, m, nvidia_re)) {
      out.push_back(at(m[1], m[2], m[3], m[4]));
    } else if (std::regex_match(line, m, glslang_bare_re) && m[2] != "") {
      out.push_back({fallback_file, 0, lower(m[1]), m[2]});
    }
  }
  return out;
}

}  // namespace pn
