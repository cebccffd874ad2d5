#include "shader/export_source.h"

#include <algorithm>
#include <cctype>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <regex>
#include <sstream>

#include "core/content_hash.h"
#include "core/error.h"
#include "shader/flatten.h"
#include "shader/target.h"

namespace pn {

std::string export_entry(const SourceTree& tree, const std::string& module) {
  const std::filesystem::path file = tree.locate(module);
  const std::string name = tree.display_name(file);
  const std::string extension = file.extension().string();
  if (extension == ".comp" || extension == ".vert" || extension == ".frag") return name;  // a pass: its own entry
  // Issue 39 C17: a header (blur.h) or any other file has no entry point; it used to give an empty shader.
  if (extension != ".glsl")
    throw Error("'" + name + "': neither a module (.glsl, exported through exports/X.comp) nor a pass (.comp, .vert, "
                ".frag): expected one of those (a header is included by its module)");
  const std::string entry = "exports/" + file.stem().string() + ".comp";
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(tree.root() / entry, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw Error("module '" + name + "': its export entry " + entry + " is " +
                (std::filesystem::is_directory(status) ? "a directory" : "not a regular file (a FIFO or a device)") +
                ": expected a GLSL file");
  if (!std::filesystem::is_regular_file(status))
    throw Error("module '" + name + "': no export entry " + entry +
                " (HLSL and MSL keep only what an entry calls): export one of its passes instead, e.g. passes/" +
                file.stem().string() + "_query.comp");
  return entry;
}

// The declarations in the exported `code` of the resource at GLSL `binding`, as the code spells
// them (issue 41: the header is read from the code, not written from a rule beside it): HLSL's
// `… : register(xN)` lines (a read-only storage buffer is a `ByteAddressBuffer` at tN, a
// combined sampler a texture at tN and its `SamplerState` at sN), MSL's kernel parameters at
// `[[texture(N)]]`, `[[sampler(N)]]`, `[[buffer(N)]]` (an image written only is `access::write`).
std::vector<std::string> declarations_of(const std::string& code, CrossLanguage language, unsigned binding,
                                         const RegisterPlan& plan) {
  std::vector<std::string> out;
  const std::string n = std::to_string(binding);
  if (language == CrossLanguage::msl) {
    // The kernel's parameters, split at the commas outside <> and ().
    const std::size_t kernel = code.find("kernel void ");
    const std::size_t open = kernel == std::string::npos ? kernel : code.find('(', kernel);
    if (open == std::string::npos) return out;
    std::vector<std::string> parameters(1);
    int depth = 0;
    for (std::size_t i = open + 1; i < code.size() && depth >= 0; ++i) {
      const char c = code[i];
      if (c == '<' || c == '(') ++depth;
      if (c == '>' || c == ')') --depth;
      if (depth < 0) break;
      if (c == ',' && depth == 0) parameters.emplace_back();
      else parameters.back() += c;
    }
    const std::regex at(R"(^\s*(.*\[\[(texture|sampler|buffer)\((\d+)\)\]\])\s*$)");
    for (const std::string& p : parameters) {
      std::smatch m;
      if (std::regex_match(p, m, at) && m[3] == n) out.push_back(m[1].str());
    }
    return out;
  }
  const std::regex declaration(R"(^\s*(.*?)\s*:\s*register\(([tsub])(\d+)(, space\d+)?\))");
  std::istringstream lines(code);
  for (std::string line; std::getline(lines, line);) {
    // Only a declaration names a register: the regex (slow in libstdc++) reads those lines alone.
    if (line.find("register(") == std::string::npos) continue;
    std::smatch m;
    if (std::regex_search(line, m, declaration) && std::stoul(m[3].str()) == binding + plan.shift(m[2].str()[0]))
      out.push_back(m[1].str() + " : register(" + m[2].str() + m[3].str() + m[4].str() + ")");
  }
  return out;
}

EntrySpirv compile_entry(const GlslangProcess& process, const SourceTree& tree, const std::string& module) {
  EntrySpirv out;
  out.entry = export_entry(tree, module);
  out.flat = flatten(tree, tree.locate_in_root(out.entry));
  CompileResult compiled = compile_with_glslang(process, standalone_source(out.flat, Target::vulkan), Target::vulkan);
  if (!compiled.ok)
    throw Error(out.entry + ": " + first_error(compiled, "glslang could not compile it for Vulkan"), ExitCode::failed);
  out.spirv = std::move(compiled.spirv);
  return out;
}

namespace {

bool is_identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// The first whole-word `word` in `text` at or after `from` (npos: none).
std::size_t find_word(const std::string& text, const std::string& word, std::size_t from = 0) {
  for (std::size_t found = text.find(word, from); found != std::string::npos; found = text.find(word, found + 1)) {
    const std::size_t end = found + word.size();
    if ((found == 0 || !is_identifier_char(text[found - 1])) && (end == text.size() || !is_identifier_char(text[end])))
      return found;
  }
  return std::string::npos;
}

// `text` with every whole-word `from` replaced by `to`.
std::string renamed(const std::string& text, const std::string& from, const std::string& to) {
  std::string out;
  std::size_t at = 0;
  for (std::size_t found = find_word(text, from); found != std::string::npos; found = find_word(text, from, at)) {
    out += text.substr(at, found - at) + to;
    at = found + from.size();
  }
  return out + text.substr(at);
}

// The number at the start of `text` (after spaces), as a float; nullopt when none.
std::optional<float> leading_float(const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const float value = std::strtof(begin, &end);
  if (end == begin) return std::nullopt;
  return value;
}

// Each top-level `const T NAME[n] = T[](T(x, …` of the flattened GLSL: its name, length and first value.
struct ConstantArray {
  std::string name;
  unsigned length;
  float first;
};
std::vector<ConstantArray> constant_arrays(const std::string& glsl) {
  std::vector<ConstantArray> out;
  const std::regex declaration(R"(^const\s+\w+\s+(\w+)\s*\[\s*(\d+)\s*\]\s*=\s*\w+\s*\[\s*\d*\s*\]\s*\(\s*(\w+\s*\(\s*)?)");
  for (std::size_t at = 0; at < glsl.size();) {
    const std::size_t end = std::min(glsl.find('\n', at), glsl.size());
    if (glsl.compare(at, 6, "const ") == 0) {
      const std::string window = glsl.substr(at, 400);  // the declaration and its first value
      std::smatch m;
      if (std::regex_search(window, m, declaration))
        if (const std::optional<float> first = leading_float(window.substr(static_cast<std::size_t>(m.length(0)))))
          out.push_back({m[1].str(), static_cast<unsigned>(std::stoul(m[2].str())), *first});
    }
    at = end + 1;
  }
  return out;
}

// `code` with each of the GLSL's constant arrays under its own name again: SPIRV-Cross names a
// constant by its id. An array whose length and first value two constants share keeps the id.
std::string named_arrays(std::string code, const std::string& glsl, CrossLanguage language) {
  const std::regex hlsl_array(R"(^static const \w+ (_\d+)\[(\d+)\] = \{ (\w+\()?)");
  const std::regex msl_array(R"(^constant spvUnsafeArray<\w+, (\d+)> (_\d+) = spvUnsafeArray<\w+, \d+>\(\{ (\w+\()?)");
  struct Found {
    std::string id;
    unsigned length;
    float first;
  };
  std::vector<Found> found;
  std::istringstream lines(code);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("static const ", 0) != 0 && line.rfind("constant spvUnsafeArray<", 0) != 0) continue;
    std::smatch m;
    const bool msl = language == CrossLanguage::msl;
    if (!std::regex_search(line, m, msl ? msl_array : hlsl_array)) continue;
    const std::optional<float> first = leading_float(line.substr(static_cast<std::size_t>(m.length(0))));
    if (!first) continue;
    found.push_back({m[msl ? 2 : 1].str(), static_cast<unsigned>(std::stoul(m[msl ? 1 : 2].str())), *first});
  }
  for (const ConstantArray& array : constant_arrays(glsl)) {
    const auto same = [&](const Found& f) { return f.length == array.length && f.first == array.first; };
    const auto match = std::find_if(found.begin(), found.end(), same);
    if (match == found.end() || std::count_if(found.begin(), found.end(), same) != 1) continue;
    if (find_word(code, array.name) != std::string::npos) continue;  // the name is taken in the code
    code = renamed(code, match->id, array.name);
  }
  return code;
}

// Each `#define PN_X <number>` of the modules' headers (.h outside exports/ and passes/) as a
// constant of `language`.
std::string named_constants(const FlatSource& flat, CrossLanguage language) {
  const std::regex define(R"(^#define (PN_[A-Z0-9_]+) (-?\d+(\.\d*)?([eE][-+]?\d+)?)\s*(//.*)?$)");
  const std::regex line_marker(R"(^#line \d+ (\d+))");
  std::string out, file;
  std::istringstream lines(flat.text);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (line.rfind("#line ", 0) == 0 && std::regex_search(line, m, line_marker)) {
      const std::size_t number = std::stoul(m[1].str());
      file = number < flat.files.size() ? flat.files[number] : "";
      continue;
    }
    const bool header = file.size() > 2 && file.compare(file.size() - 2, 2, ".h") == 0 && file.rfind("exports/", 0) != 0 &&
                        file.rfind("passes/", 0) != 0;
    if (!header || line.rfind("#define PN_", 0) != 0 || !std::regex_match(line, m, define)) continue;
    const bool real = m[3].matched || m[4].matched;
    const std::string value = m[2].str() + (real && language != CrossLanguage::msl ? "f" : "");
    out += std::string(language == CrossLanguage::msl ? "constant " : "static const ") + (real ? "float " : "int ") +
           m[1].str() + " = " + value + ";  // " + file + "\n";
  }
  return out;
}

// The leading `//` lines of `text`.
std::string leading_comment(const std::string& text) {
  std::string out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line) && line.rfind("//", 0) == 0;) out += line + "\n";
  return out;
}

}  // namespace

std::string export_code(const std::vector<std::uint32_t>& spirv, const FlatSource& flat, CrossLanguage language,
                        const RegisterPlan& plan) {
  const std::string code = named_arrays(cross_compile(spirv, language, plan), flat.text, language);
  const std::string constants = named_constants(flat, language);
  if (constants.empty()) return code;
  const std::string block = "// The modules' named constants (their headers' #defines), for the settings' fields:\n" +
                            constants + "\n";
  // MSL: after its includes and `using namespace metal;`.
  const std::size_t metal = code.find("using namespace metal;\n");
  const std::size_t at = metal == std::string::npos ? 0 : metal + std::string("using namespace metal;\n").size();
  return code.substr(0, at) + (at == 0 ? "" : "\n") + block + code.substr(at);
}

std::string export_source(const GlslangProcess& process, const SourceTree& tree, const std::string& module,
                          CrossLanguage language, const std::string& provenance, const RegisterPlan& plan) {
  const EntrySpirv compiled = compile_entry(process, tree, module);
  const std::string& entry = compiled.entry;
  const FlatSource& flat = compiled.flat;
  const std::string text = export_code(compiled.spirv, flat, language, plan);
  const std::filesystem::path file = tree.locate(module);

  std::string header = "// penumbra bundle of " + tree.display_name(file) + " as " +
                       cross_language_name(language) + " (generated by `penumbra bundle`; do not edit: regenerate)\n";
  header += "// made: " + entry + " (GLSL 450, vulkan target) -> SPIR-V 1.0 (glslang) -> " +
            cross_language_name(language) + " (SPIRV-Cross)\n";
  if (!provenance.empty()) header += "// from: " + provenance + "\n";
  header += "// files (FNV-1a 64 of each):\n";
  for (const std::string& f : flat.files)
    header += "//   " + content_hash(tree.read(tree.locate_in_root(f))) + "  " + f + "\n";
  header += language == CrossLanguage::msl
                ? "// bindings: GLSL binding N at index N ([[texture(N)]], [[sampler(N)]], [[buffer(N)]]), as the "
                  "kernel declares each:\n"
            : plan.identity()
                ? "// bindings: GLSL binding N at register N of its kind (t: texture or read-only buffer, s: its "
                  "sampler, GLSL's combined samplers split; u: image or read-write buffer; b: cbuffer), space 0, as "
                  "the code declares each:\n"
                : "// bindings: GLSL binding N at register N + the shift of its kind (t: texture or read-only buffer, "
                  "s: its sampler, GLSL's combined samplers split; u: image or read-write buffer; b: cbuffer) — the "
                  "plan " + plan.describe() + " (--register-shift, --register-space) — as the code declares each:\n";
  for (const SpirvBinding& b : reflect_spirv(compiled.spirv).bindings) {
    std::string where;
    for (const std::string& d : declarations_of(text, language, b.binding, plan))
      where += (where.empty() ? "" : "; ") + d;
    if (where.empty()) where = "unused: not in the code";
    header += "//   " + b.name + " (GLSL binding " + std::to_string(b.binding) + "): " + where + "\n";
  }
  const std::string own = leading_comment(tree.read(file));
  if (!own.empty()) header += "//\n// " + tree.display_name(file) + "'s own comment (GLSL's names):\n" + own;
  return header + text;
}

}  // namespace pn
