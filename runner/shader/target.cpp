#include "core/decimal.h"
#include "shader/target.h"

#include <climits>
#include <sstream>

#include "core/error.h"

namespace pn {

std::string define_key(const std::vector<Define>& defines) {
  std::string key;
  for (const Define& d : defines) key += d.name + "=" + d.value + ";";
  return key;
}

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

// "#line LINE FILE", both decimal: the flattener's markers. Scanned by hand, not
// with std::regex, whose recursion per character overflowed the stack on a
// 30,000-digit marker (docs/reliability.md, "Fuzzing").
bool line_marker(const std::string& line, std::string* line_number = nullptr, std::string* file_number = nullptr) {
  const auto digits = [&](size_t& i) {
    const size_t begin = i;
    while (i < line.size() && line[i] >= '0' && line[i] <= '9') ++i;
    return i > begin;
  };
  size_t i = 6;
  if (line.compare(0, 6, "#line ") != 0 || !digits(i)) return false;
  const size_t first_end = i;
  if (i >= line.size() || line[i] != ' ') return false;
  const size_t second = ++i;
  if (!digits(i) || i != line.size()) return false;
  if (line_number) *line_number = line.substr(6, first_end - 6);
  if (file_number) *file_number = line.substr(second);
  return true;
}

}  // namespace

std::string ShaderSource::driver_text() const {
  std::istringstream lines(text);
  std::string out, line;
  while (std::getline(lines, line)) out += (line_marker(line) ? "" : line) + "\n";
  return out;
}

std::pair<std::string, int> ShaderSource::origin_of_line(int line) const {
  std::istringstream lines(text);
  std::string current, line_number, file_number;
  std::pair<std::string, int> next{"<wrapper>", 1}, origin{"<wrapper>", 0};
  for (int physical = 1; physical <= line && std::getline(lines, current); ++physical) {
    if (line_marker(current, &line_number, &file_number)) {
      const size_t number = static_cast<size_t>(saturating_decimal(file_number));
      next = {number < files.size() ? files[number] : "<wrapper>", saturating_decimal(line_number)};
      origin = {"<wrapper>", 0};
    } else {
      origin = next;
      if (next.second < INT_MAX) ++next.second;  // after `#line 2147483647`: saturate like the marker's number
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
