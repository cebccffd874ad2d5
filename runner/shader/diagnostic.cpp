#include "shader/diagnostic.h"

#include <regex>
#include <sstream>

namespace pn {

std::string Diagnostic::str() const {
  std::string out = file;
  if (line > 0) out += ":" + std::to_string(line);
  return out + ": " + severity + ": " + message;
}

std::vector<Diagnostic> parse_info_log(const std::string& log, const std::vector<std::string>& files,
                                       const std::string& fallback_file) {
  // glslang: "ERROR: 2:14: 'x' : undeclared identifier"
  // Mesa:    "2:14(3): error: `x' undeclared"
  static const std::regex glslang_re(R"(^(ERROR|WARNING): (\d+):(\d+): (.*?)\s*$)");
  static const std::regex glslang_bare_re(R"(^(ERROR|WARNING): (.*?)\s*$)");
  static const std::regex mesa_re(R"(^(\d+):(\d+)\(\d+\): (error|warning): (.*?)\s*$)");
  static const std::regex summary_re(R"(^(ERROR|WARNING): \d+ compilation (errors|warnings)\..*)");

  auto file_name = [&](const std::string& number) {
    size_t n = std::stoul(number);
    return n < files.size() ? files[n] : fallback_file;
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
    if (std::regex_match(line, summary_re)) continue;
    if (std::regex_match(line, m, glslang_re)) {
      out.push_back({file_name(m[2]), std::stoi(m[3]), lower(m[1]), m[4]});
    } else if (std::regex_match(line, m, mesa_re)) {
      out.push_back({file_name(m[1]), std::stoi(m[2]), m[3], m[4]});
    } else if (std::regex_match(line, m, glslang_bare_re)) {
      if (m[2] != "" && m[2] != "'' : compilation terminated")
        out.push_back({fallback_file, 0, lower(m[1]), m[2]});
    }
  }
  return out;
}

}  // namespace pn
