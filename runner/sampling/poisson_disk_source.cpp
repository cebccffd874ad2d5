#include "sampling/poisson_disk_source.h"

#include <cctype>
#include <cstdio>
#include <regex>
#include <set>

#include "core/error.h"

namespace pn {

namespace {

// What a language writes: its --lang key, its name with the article before it, the array's
// declaration around NAME[n] and a point's format.
struct LanguageForm {
  SourceLanguage language;
  const char* key;
  const char* named;  // "a GLSL", "an HLSL"
  const char* type;   // before NAME
  const char* open;   // after [n]
  const char* point;  // x, y, separator
  const char* close;
};

constexpr LanguageForm kForms[] = {
    {SourceLanguage::glsl, "glsl", "a GLSL", "const vec2 ", "] = vec2[](\n", "    vec2(%s, %s)%s\n", ");\n"},
    {SourceLanguage::hlsl, "hlsl", "an HLSL", "static const float2 ", "] = {\n", "    float2(%s, %s)%s\n", "};\n"},
    {SourceLanguage::msl, "msl", "an MSL", "constant float2 ", "] = {\n", "    float2(%s, %s)%s\n", "};\n"},
    {SourceLanguage::cpp, "cpp", "a C++", "constexpr float ", "][2] = {\n", "    {%s, %s}%s\n", "};\n"}};

const LanguageForm& form_of(SourceLanguage language) {
  for (const LanguageForm& f : kForms)
    if (f.language == language) return f;
  return kForms[0];
}

// GLSL 4.50 §3.6 (and ES 3.10 §3.7): keywords and reserved words — a name the compiler refuses.
bool glsl_keyword_or_reserved(const std::string& name) {
  static const std::set<std::string> words{
      // keywords
      "const", "uniform", "buffer", "shared", "attribute", "varying", "coherent", "volatile", "restrict", "readonly",
      "writeonly", "atomic_uint", "layout", "centroid", "flat", "smooth", "noperspective", "patch", "sample",
      "invariant", "precise", "break", "continue", "do", "for", "while", "switch", "case", "default", "if", "else",
      "subroutine", "in", "out", "inout", "int", "void", "bool", "true", "false", "float", "double", "discard",
      "return", "uint", "lowp", "mediump", "highp", "precision", "struct",
      // reserved for future use
      "common", "partition", "active", "asm", "class", "union", "enum", "typedef", "template", "this", "resource",
      "goto", "inline", "noinline", "public", "static", "extern", "external", "interface", "long", "short", "half",
      "fixed", "unsigned", "superp", "input", "output", "filter", "sizeof", "cast", "namespace", "using"};
  if (words.count(name)) return true;
  // The type families: vectors (vec3, ivec2, hvec4, ...), matrices (mat3, dmat2x4), samplers and images.
  static const std::regex types("[ibudhf]?vec[234]|d?mat[234](x[234])?|[iu]?(sampler|image|texture)[0-9A-Z].*");
  return std::regex_match(name, types);
}

// C++20's keywords and alternative tokens ([lex.key], [lex.digraph]): MSL is C++14 and HLSL shares
// most of them.
bool cpp_keyword(const std::string& name) {
  static const std::set<std::string> words{
      "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break", "case", "catch",
      "char", "char8_t", "char16_t", "char32_t", "class", "compl", "concept", "const", "consteval", "constexpr",
      "constinit", "const_cast", "continue", "co_await", "co_return", "co_yield", "decltype", "default", "delete",
      "do", "double", "dynamic_cast", "else", "enum", "explicit", "export", "extern", "false", "float", "for",
      "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq",
      "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register", "reinterpret_cast",
      "requires", "return", "short", "signed", "sizeof", "static", "static_assert", "static_cast", "struct",
      "switch", "template", "this", "thread_local", "throw", "true", "try", "typedef", "typeid", "typename", "union",
      "unsigned", "using", "virtual", "void", "volatile", "wchar_t", "while", "xor", "xor_eq"};
  return words.count(name) > 0;
}

// HLSL's keywords (the HLSL reference's "Keywords" page) and its type names: scalars, vectors and
// matrices (float3, min16int2x4), textures, buffers and samplers.
bool hlsl_keyword(const std::string& name) {
  static const std::set<std::string> words{
      "AppendStructuredBuffer", "BlendState", "bool", "break", "Buffer", "ByteAddressBuffer", "case", "cbuffer",
      "centroid", "class", "column_major", "compile", "compile_fragment", "CompileShader", "const", "continue",
      "ComputeShader", "ConsumeStructuredBuffer", "default", "DepthStencilState", "DepthStencilView", "discard",
      "do", "double", "DomainShader", "dword", "else", "export", "extern", "false", "float", "for", "fxgroup",
      "GeometryShader", "groupshared", "half", "Hullshader", "if", "in", "inline", "inout", "InputPatch",
      "interface", "line", "lineadj", "linear", "LineStream", "matrix", "min16float", "min10float", "min16int",
      "min12int", "min16uint", "namespace", "nointerpolation", "noperspective", "NULL", "out", "OutputPatch",
      "packoffset", "pass", "pixelfragment", "PixelShader", "point", "PointStream", "precise",
      "RasterizerState", "RenderTargetView", "return", "register", "row_major", "RWBuffer",
      "RWByteAddressBuffer", "RWStructuredBuffer", "RWTexture1D", "RWTexture1DArray", "RWTexture2D",
      "RWTexture2DArray", "RWTexture3D", "sample", "sampler", "SamplerState", "SamplerComparisonState", "shared",
      "snorm", "stateblock", "stateblock_state", "static", "string", "struct", "switch", "StructuredBuffer",
      "tbuffer", "technique", "technique10", "technique11", "texture", "Texture1D", "Texture1DArray", "Texture2D",
      "Texture2DArray", "Texture2DMS", "Texture2DMSArray", "Texture3D", "TextureCube", "TextureCubeArray", "true",
      "typedef", "triangle", "triangleadj", "TriangleStream", "uint", "uniform", "unorm", "unsigned", "vector",
      "vertexfragment", "VertexShader", "void", "volatile", "while"};
  static const std::regex types("(bool|int|uint|dword|half|float|double|min16float|min10float|min16int|min12int|"
                                "min16uint)[1-4](x[1-4])?");
  return words.count(name) > 0 || std::regex_match(name, types);
}

// MSL's own keywords and type names beyond C++14's (the Metal Shading Language Specification §2, §4,
// §5): address spaces, function qualifiers, vectors and matrices (float3, half2x4).
bool msl_keyword(const std::string& name) {
  static const std::set<std::string> words{"constant", "device", "threadgroup", "threadgroup_imageblock", "thread",
                                           "ray_data", "object_data", "kernel", "vertex", "fragment", "visible",
                                           "half", "uchar", "ushort", "uint", "ulong", "bfloat", "metal",
                                           "sampler", "texture1d", "texture2d", "texture3d", "texturecube"};
  static const std::regex types("(bool|char|uchar|short|ushort|int|uint|long|ulong|half|float|bfloat)[2-4](x[2-4])?");
  return words.count(name) > 0 || std::regex_match(name, types);
}

// A float to 9 significant digits (it reads back exactly); in C++ a float literal (1.0f, 5e-05f).
std::string number(float v, SourceLanguage language) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(v));
  std::string out = text;
  if (language != SourceLanguage::cpp) return out;
  if (out.find_first_of(".e") == std::string::npos) out += ".0";
  return out + "f";
}

bool reserved(const std::string& name, SourceLanguage language) {
  switch (language) {
    case SourceLanguage::glsl: return glsl_keyword_or_reserved(name);
    case SourceLanguage::hlsl: return hlsl_keyword(name) || cpp_keyword(name);
    case SourceLanguage::msl: return msl_keyword(name) || cpp_keyword(name);
    case SourceLanguage::cpp: return cpp_keyword(name);
  }
  return false;
}

}  // namespace

SourceLanguage parse_source_language(const std::string& name) {
  for (const LanguageForm& f : kForms)
    if (name == f.key) return f.language;
  throw Error("--lang '" + name + "': expected glsl, hlsl, msl or cpp");
}

std::string poisson_disk_source(const PoissonDisk& disk, const std::string& name, std::uint32_t seed,
                                SourceLanguage language) {
  const LanguageForm& form = form_of(language);
  // An identifier (GLSL ES 3.10 §3.7, C++ [lex.name] without universal characters): a letter or _,
  // then letters, digits and _; names beginning with gl_ or holding __ are reserved (GLSL; in C++
  // and its kin __ is the implementation's); at most 1024 characters.
  bool identifier = !name.empty() && name.size() <= 1024 && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                    (language != SourceLanguage::glsl || name.rfind("gl_", 0) != 0) &&
                    name.find("__") == std::string::npos;
  for (char c : name) identifier = identifier && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  if (!identifier)
    throw Error("Poisson disk name '" + name + "': expected " + form.named + " identifier (letters, digits and _, not " +
                "starting with a digit" + (language == SourceLanguage::glsl ? " or gl_" : "") + ", no __)");
  if (reserved(name, language))
    throw Error("Poisson disk name '" + name + "': " + form.named + " keyword or reserved word: expected another identifier");
  char line[96];
  std::snprintf(line, sizeof line, "// %zu Poisson-disk samples in the unit disk, minimum distance %.6f,\n",
                disk.points.size(), disk.min_distance);
  std::string out = line;
  // GLSL's without --lang: the text GLSL files hold (poisson_pcss_query.comp).
  const std::string lang = language == SourceLanguage::glsl ? "" : std::string(" --lang ") + form.key;
  std::snprintf(line, sizeof line, "// Bridson's algorithm, seed %u (penumbra poisson%s).\n", seed, lang.c_str());
  out += line;
  out += form.type + name + "[" + std::to_string(disk.points.size()) + form.open;
  for (size_t i = 0; i < disk.points.size(); ++i) {
    std::string x = number(disk.points[i].x, language), y = number(disk.points[i].y, language);
    std::snprintf(line, sizeof line, form.point, x.c_str(), y.c_str(), i + 1 < disk.points.size() ? "," : "");
    out += line;
  }
  return out + form.close;
}

std::string poisson_disk_glsl(const PoissonDisk& disk, const std::string& name, std::uint32_t seed) {
  return poisson_disk_source(disk, name, seed, SourceLanguage::glsl);
}

}  // namespace pn
