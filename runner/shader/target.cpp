#include "core/decimal.h"
#include "shader/target.h"

#include <regex>
#include <sstream>

#include "core/error.h"

namespace pn {

const std::vector<Target>& all_targets() {
  static const std::vector<Target> targets{Target::gl450, Target::vulkan, Target::es310};
  return targets;
}

const char* target_name(Target target) {
  switch (target) {
    case Target::gl450: return "gl450";
    case Target::vulkan: return "vulkan";
    case Target::es310: return "es310";
  }
  return "?";
}

Target parse_target(const std::string& name) {
  for (Target t : all_targets())
    if (name == target_name(t)) return t;
  throw Error("target '" + name + "': expected one of gl450, vulkan, es310");
}

namespace {

const std::regex& line_marker() {
  static const std::regex re(R"(^#line (\d+) (\d+)$)");
  return re;
}

}  // namespace

std::string ShaderSource::driver_text() const {
  std::istringstream lines(text);
  std::string out, line;
  while (std::getline(lines, line)) out += (std::regex_match(line, line_marker()) ? "" : line) + "\n";
  return out;
}

std::pair<std::string, int> ShaderSource::origin_of_line(int line) const {
  std::istringstream lines(text);
  std::string current;
  std::pair<std::string, int> next{"<wrapper>", 1}, origin{"<wrapper>", 0};
  std::smatch m;
  for (int physical = 1; physical <= line && std::getline(lines, current); ++physical) {
    if (std::regex_match(current, m, line_marker())) {
      const size_t number = static_cast<size_t>(saturating_decimal(m[2]));
      next = {number < files.size() ? files[number] : "<wrapper>", saturating_decimal(m[1])};
      origin = {"<wrapper>", 0};
    } else {
      origin = next;
      ++next.second;
    }
  }
  return origin;
}

ShaderSource standalone_source(const FlatSource& flat, Target target, const std::vector<Define>& defines) {
  ShaderSource out;
  switch (target) {
    case Target::gl450: out.text = "#version 450 core\n"; break;
    case Target::vulkan: out.text = "#version 450\n"; break;
    case Target::es310:
      // ES has no default precision for images and only lowp for samplers.
      out.text =
          "#version 310 es\n"
          "precision highp float;\nprecision highp int;\n"
          "precision highp sampler2D;\nprecision highp isampler2D;\nprecision highp usampler2D;\n"
          "precision highp sampler2DArray;\nprecision highp isampler2DArray;\nprecision highp usampler2DArray;\n"
          "precision highp image2D;\nprecision highp iimage2D;\nprecision highp uimage2D;\n"
          "precision highp image2DArray;\nprecision highp iimage2DArray;\nprecision highp uimage2DArray;\n";
      break;
  }
  for (const Define& d : defines) out.text += "#define " + d.name + " " + d.value + "\n";
  out.text += flat.file_table_comment();
  out.text += flat.text;
  out.files = flat.files;
  out.stage = flat.stage;
  if (!flat.has_main) {
    out.text += "#line 1 " + std::to_string(out.files.size()) + "\n";
    out.text += "layout(local_size_x = 1) in;\nvoid main() {}\n";
    out.files.push_back("<penumbra standalone entry point>");
  }
  return out;
}

}  // namespace pn
