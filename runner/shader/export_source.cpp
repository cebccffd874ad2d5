#include "shader/export_source.h"

#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <sstream>

#include "core/error.h"
#include "shader/flatten.h"
#include "shader/target.h"

namespace pn {

std::string content_hash(const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : text) h = (h ^ c) * 0x100000001b3ull;
  char out[17];
  std::snprintf(out, sizeof out, "%016" PRIx64, h);
  return out;
}

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
std::vector<std::string> declarations_of(const std::string& code, CrossLanguage language, unsigned binding) {
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
    if (std::regex_search(line, m, declaration) && m[3] == n)
      out.push_back(m[1].str() + " : register(" + m[2].str() + n + m[4].str() + ")");
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

std::string export_source(const GlslangProcess& process, const SourceTree& tree, const std::string& module,
                          CrossLanguage language, const std::string& provenance) {
  const EntrySpirv compiled = compile_entry(process, tree, module);
  const std::string& entry = compiled.entry;
  const FlatSource& flat = compiled.flat;
  const std::string text = cross_compile(compiled.spirv, language);

  std::string header = "// penumbra bundle of " + tree.display_name(tree.locate(module)) + " as " +
                       cross_language_name(language) + " (generated by `penumbra bundle`; do not edit: regenerate)\n";
  header += "// made: " + entry + " (GLSL 450, vulkan target) -> SPIR-V 1.0 (glslang) -> " +
            cross_language_name(language) + " (SPIRV-Cross)\n";
  if (!provenance.empty()) header += "// from: " + provenance + "\n";
  header += "// files (FNV-1a 64 of each):\n";
  for (const std::string& file : flat.files)
    header += "//   " + content_hash(tree.read(tree.locate_in_root(file))) + "  " + file + "\n";
  header += language == CrossLanguage::msl
                ? "// bindings: GLSL binding N at index N ([[texture(N)]], [[sampler(N)]], [[buffer(N)]]), as the "
                  "kernel declares each:\n"
                : "// bindings: GLSL binding N at register N of its kind (t: texture or read-only buffer, s: its "
                  "sampler, GLSL's combined samplers split; u: image or read-write buffer; b: cbuffer), space 0, as "
                  "the code declares each:\n";
  for (const SpirvBinding& b : reflect_spirv(compiled.spirv).bindings) {
    std::string where;
    for (const std::string& d : declarations_of(text, language, b.binding)) where += (where.empty() ? "" : "; ") + d;
    if (where.empty()) where = "unused: not in the code";
    header += "//   " + b.name + " (GLSL binding " + std::to_string(b.binding) + "): " + where + "\n";
  }
  return header + text;
}

}  // namespace pn
