#include "shader/pass_interface.h"

#include <algorithm>
#include <regex>
#include <sstream>

#include "shader/export_source.h"
#include "shader/register_plan.h"
#include "shader/spirv_cross.h"

namespace pn {

namespace {

std::string kind_text(const SpirvBinding& b) {
  switch (b.kind) {
    case DescriptorKind::combined_image_sampler: return "sampler (texture + sampler)";
    case DescriptorKind::sampled_image: return "texture";
    case DescriptorKind::sampler: return "sampler state";
    case DescriptorKind::storage_image: return b.integer ? "integer image" : "image";
    case DescriptorKind::uniform_buffer: return "uniform block";
    case DescriptorKind::storage_buffer: return "storage buffer";
  }
  return "?";
}

// The registers the HLSL declares at `binding` ("t0, s0"), read from the HLSL itself.
std::string registers(const std::string& hlsl, unsigned binding) {
  std::string out;
  const std::regex reg(R"(register\(([tsub]\d+)(, space\d+)?\))");
  for (const std::string& d : declarations_of(hlsl, CrossLanguage::hlsl50, binding)) {
    std::smatch m;
    if (std::regex_search(d, m, reg)) out += (out.empty() ? "" : ", ") + m[1].str();
  }
  return out.empty() ? "—" : out;
}

// The comment that says what a resource holds: on the #define of the binding its declaration names
// (`#define PN_X_BINDING 0  // sampler2D, R32F`), else on the declaration's own line.
std::string holds(const std::string& glsl, const std::string& name) {
  std::istringstream lines(glsl);
  std::string declaration;
  const std::regex named("\\b" + name + "\\b");
  for (std::string line; std::getline(lines, line);)
    if (line.find("#define") == std::string::npos && line.find_first_not_of(" \t") != line.find("//") &&
        std::regex_search(line, named) &&
        (line.find("binding") != std::string::npos || line.find("_BINDING") != std::string::npos)) {
      declaration = line;
      break;
    }
  if (declaration.empty()) return "";
  std::smatch m;
  if (std::regex_search(declaration, m, std::regex(R"(binding\s*=\s*(PN_\w+))")) ||
      std::regex_search(declaration, m, std::regex(R"(\b(PN_\w*_BINDING)\b)"))) {
    std::smatch d;
    if (std::regex_search(glsl, d, std::regex("#define\\s+" + m[1].str() + "\\s+\\d+[ \\t]*//[ \\t]*([^\\n]*)")))
      return d[1].str();
  }
  const std::size_t text = declaration.find("//") == std::string::npos
                               ? std::string::npos
                               : declaration.find_first_not_of(" /", declaration.find("//"));
  return text == std::string::npos ? "" : declaration.substr(text);
}

// A block's members, comments dropped ("int level; int texelFirst; int texelCount;"): what an
// engine fills (PN_UNIFORM_BLOCK(Name, …) … PN_END_UNIFORM_BLOCK, or `Name { … }`).
std::string members(const std::string& glsl, const std::string& block) {
  std::size_t open = glsl.find("\nPN_UNIFORM_BLOCK(" + block + ",");  // at a line's start: not a comment's example
  std::size_t close = std::string::npos;
  if (open != std::string::npos) {
    open = glsl.find('\n', open + 1);
    close = glsl.find("PN_END_UNIFORM_BLOCK", open);
  } else {
    std::smatch m;
    if (!std::regex_search(glsl, m, std::regex("\\b" + block + "\\s*\\{"))) return "";
    open = static_cast<std::size_t>(m.position(0) + m.length(0));
    close = glsl.find('}', open);
  }
  if (open == std::string::npos || close == std::string::npos) return "";
  std::istringstream lines(glsl.substr(open, close - open));
  std::string out;
  for (std::string line; std::getline(lines, line);) {
    line = line.substr(0, line.find("//"));
    const std::size_t first = line.find_first_not_of(" \t"), last = line.find_last_not_of(" \t");
    if (first != std::string::npos) out += (out.empty() ? "" : " ") + line.substr(first, last - first + 1);
  }
  return out;
}

std::string escaped(std::string text) {
  for (std::size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2)) text.replace(at, 1, "\\|");
  return text;
}

}  // namespace

std::vector<InterfaceRow> pass_interface(const GlslangProcess& process, const SourceTree& tree, const std::string& module) {
  const EntrySpirv compiled = compile_entry(process, tree, module);
  const FlatSource& flat = compiled.flat;
  const std::string hlsl = cross_compile(compiled.spirv, CrossLanguage::hlsl50, RegisterPlan{});
  const SpirvReflection all = reflect_spirv(compiled.spirv), active = reflect_spirv(compiled.spirv, true);
  std::vector<InterfaceRow> rows;
  for (const SpirvBinding& b : all.bindings) {
    InterfaceRow r;
    r.binding = b.binding;
    r.name = b.name;
    r.kind = kind_text(b);
    r.hlsl = registers(hlsl, b.binding);
    r.format = b.format;
    // A storage buffer's readonly is on its members, not the variable: HLSL's t register says it.
    const bool read_only = b.kind == DescriptorKind::storage_buffer ? r.hlsl.rfind('t', 0) == 0 : b.non_writable;
    const bool writes = b.kind == DescriptorKind::storage_image || b.kind == DescriptorKind::storage_buffer;
    r.access = !writes || read_only ? "read" : b.non_readable ? "write" : "read-write";
    r.used = std::any_of(active.bindings.begin(), active.bindings.end(),
                         [&](const SpirvBinding& a) { return a.binding == b.binding && a.set == b.set; });
    const bool block = b.kind == DescriptorKind::uniform_buffer || b.kind == DescriptorKind::storage_buffer;
    r.holds = block ? members(flat.text, b.name) : holds(flat.text, b.name);
    rows.push_back(r);
  }
  std::sort(rows.begin(), rows.end(), [](const InterfaceRow& a, const InterfaceRow& b) { return a.binding < b.binding; });
  return rows;
}

std::string interface_markdown(const std::vector<InterfaceRow>& rows) {
  std::string out = "| binding | HLSL | name | kind | format | access | used | holds |\n"
                    "| ---: | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const InterfaceRow& r : rows)
    out += "| " + std::to_string(r.binding) + " | " + r.hlsl + " | `" + r.name + "` | " + r.kind + " | " +
           (r.format.empty() ? "—" : r.format) + " | " + r.access + " | " + (r.used ? "yes" : "no (need not be bound)") +
           " | " + escaped(r.holds) + " |\n";
  return out;
}

}  // namespace pn
