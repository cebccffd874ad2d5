#include "shader/glslang_compiler.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv-tools/libspirv.hpp>

#include "core/error.h"
#include "shader/spirv_cross.h"

namespace pn {

GlslangProcess::GlslangProcess() { glslang::InitializeProcess(); }
GlslangProcess::~GlslangProcess() { glslang::FinalizeProcess(); }

namespace {

std::vector<Diagnostic> validate_spirv(const std::vector<uint32_t>& spirv, const std::string& entry) {
  std::vector<Diagnostic> out;
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_0);
  tools.SetMessageConsumer([&](spv_message_level_t level, const char*, const spv_position_t&, const char* text) {
    if (level <= SPV_MSG_ERROR) out.push_back({entry, 0, "error", std::string("SPIR-V validation: ") + text});
  });
  // Without friendly names: the validator's name map (a string per id, made before any rule is
  // checked) was 40 % of a Vulkan check's time; its messages name ids by number instead.
  spvtools::ValidatorOptions options;
  options.SetFriendlyNames(false);
  if (!tools.Validate(spirv.data(), spirv.size(), options) && out.empty()) out.push_back({entry, 0, "error", "SPIR-V validation failed"});
  return out;
}

// Two resources of one entry at one binding (shader/spirv_cross.h shared_bindings): an error for Vulkan.
std::vector<Diagnostic> binding_clashes(const std::vector<uint32_t>& spirv, const std::string& entry) {
  std::vector<Diagnostic> out;
  for (const std::string& clash : shared_bindings(reflect_spirv(spirv)))
    out.push_back({entry, 0, "error",
                   clash + " share a binding: Vulkan has one binding namespace a descriptor set (GL keeps texture "
                           "units, image units and buffer bindings apart); give each its own number"});
  return out;
}

EShLanguage language_of(Stage stage) {
  return stage == Stage::vertex ? EShLangVertex : stage == Stage::fragment ? EShLangFragment : EShLangCompute;
}

// Parses and links `shader` (its strings and environment set), then, for Vulkan, makes SPIR-V,
// validates it and refuses bindings two resources share. `hlsl`: the registers mapped to bindings
// (mapIO, with the shader's shifts) and glslang's legalization (SPIRV-Tools passes) run.
CompileResult compile_shader(glslang::TShader& shader, EShLanguage language, EShMessages messages,
                             const LocationMap& locations, const std::string& entry, bool spirv, bool hlsl) {
  CompileResult result;
  const bool parsed = shader.parse(GetDefaultResources(), 100, ENoProfile, false, false, messages);
  result.diagnostics = parse_info_log(shader.getInfoLog(), locations, entry);
  if (!parsed) return result;

  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages) || (hlsl && !program.mapIO())) {
    auto link = parse_info_log(program.getInfoLog(), locations, entry);
    result.diagnostics.insert(result.diagnostics.end(), link.begin(), link.end());
    if (result.diagnostics.empty()) result.diagnostics.push_back({entry, 0, "error", "glslang could not link it"});
    return result;
  }
  if (spirv) {
    glslang::SpvOptions options;
    options.validate = false;  // validated below, with the messages kept
    options.disableOptimizer = !hlsl;
    glslang::GlslangToSpv(*program.getIntermediate(language), result.spirv, &options);
    auto invalid = validate_spirv(result.spirv, entry);
    if (invalid.empty()) invalid = binding_clashes(result.spirv, entry);
    if (!invalid.empty()) {
      result.diagnostics.insert(result.diagnostics.end(), invalid.begin(), invalid.end());
      return result;
    }
  }
  result.ok = true;
  for (const Diagnostic& d : result.diagnostics)
    if (d.severity == "error") result.ok = false;
  return result;
}

// The environment a GLSL shader is parsed in for `target`; returns the messages to parse with.
EShMessages glsl_environment(glslang::TShader& shader, EShLanguage stage, Target target) {
  if (target == Target::vulkan) {
    shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    return static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  }
  // Client "none" (SPEC §8): EShClientOpenGL would select ARB_gl_spirv rules.
  shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientNone, 0);
  shader.setEnvClient(glslang::EShClientNone, glslang::EShTargetClientVersion(0));
  shader.setEnvTarget(glslang::EShTargetNone, glslang::EShTargetLanguageVersion(0));
  return EShMsgDefault;
}

// The environment of an HLSL shader (its strings set): Vulkan 1.0, entry `main`, the registers'
// bindings as compile_hlsl_with_glslang documents. Returns the messages to parse with.
EShMessages hlsl_environment(glslang::TShader& shader, EShLanguage language) {
  shader.setEntryPoint("main");
  shader.setEnvInput(glslang::EShSourceHlsl, language, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  shader.setShiftBinding(glslang::EResSampler, kHlslSamplerBindingShift);
  // A raster stage's inputs and outputs (SPIRV-Cross's TEXCOORD<location> semantics) take locations
  // in their order of declaration, which SPIRV-Cross keeps in location order in both stages.
  shader.setAutoMapLocations(true);
  return static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules | EShMsgReadHlsl);
}

std::string entry_of(const ShaderSource& source) { return source.files.empty() ? "<source>" : source.files.front(); }

// The `#line` markers carry file numbers, which glslang reports faithfully.
LocationMap by_file_number(const ShaderSource& source) {
  return [&source](int number, int line) {
    const auto n = static_cast<size_t>(number);
    return std::pair<std::string, int>{n < source.files.size() ? source.files[n] : entry_of(source), line};
  };
}

// glslang's preprocessor alone (glslangValidator -E) over `shader`, its strings and environment set.
// No includer: a flattened source has no #include left, and an HLSL copy is one file.
Preprocessed preprocess(glslang::TShader& shader, EShMessages messages, const LocationMap& locations,
                        const std::string& entry) {
  Preprocessed result;
  glslang::TShader::ForbidIncluder includer;
  result.ok = shader.preprocess(GetDefaultResources(), 100, ENoProfile, false, false, messages, &result.text, includer);
  result.diagnostics = parse_info_log(shader.getInfoLog(), locations, entry);
  for (const Diagnostic& d : result.diagnostics)
    if (d.severity == "error") result.ok = false;
  if (!result.ok && result.diagnostics.empty())
    result.diagnostics.push_back({entry, 0, "error", "glslang could not preprocess it"});
  return result;
}

}  // namespace

std::string first_error(const CompileResult& result, const std::string& fallback) {
  for (const Diagnostic& d : result.diagnostics)
    if (d.severity == "error") return d.str();
  return fallback;
}

CompileResult compile_with_glslang(const GlslangProcess&, const ShaderSource& source, Target target) {
  const EShLanguage stage = language_of(source.stage);
  glslang::TShader shader(stage);
  const char* text = source.text.c_str();
  const int length = static_cast<int>(source.text.size());
  shader.setStringsWithLengths(&text, &length, 1);
  const EShMessages messages = glsl_environment(shader, stage, target);
  return compile_shader(shader, stage, messages, by_file_number(source), entry_of(source), target == Target::vulkan,
                        false);
}

Preprocessed preprocess_with_glslang(const GlslangProcess&, const ShaderSource& source, Target target) {
  const EShLanguage stage = language_of(source.stage);
  glslang::TShader shader(stage);
  const char* text = source.text.c_str();
  const int length = static_cast<int>(source.text.size());
  shader.setStringsWithLengths(&text, &length, 1);
  const EShMessages messages = glsl_environment(shader, stage, target);
  return preprocess(shader, messages, by_file_number(source), entry_of(source));
}

CompileResult compile_hlsl_with_glslang(const GlslangProcess&, const std::string& text, const std::string& name,
                                        Stage stage) {
  const EShLanguage language = language_of(stage);
  glslang::TShader shader(language);
  const char* chars = text.c_str();
  const int length = static_cast<int>(text.size());
  const char* names[] = {name.c_str()};
  shader.setStringsWithLengthsAndNames(&chars, &length, names, 1);
  const EShMessages messages = hlsl_environment(shader, language);
  const LocationMap by_name = [&](int, int line) { return std::pair<std::string, int>{name, line}; };
  // HLSL passes textures and samplers to functions by value, which Vulkan does not allow:
  // glslang's legalization (SPIRV-Tools: inlining, opaque values propagated to their variables)
  // turns that into legal SPIR-V, as glslangValidator does by default for HLSL.
  return compile_shader(shader, language, messages, by_name, name, true, true);
}

Preprocessed preprocess_hlsl_with_glslang(const GlslangProcess&, const std::string& text, const std::string& name,
                                          Stage stage) {
  const EShLanguage language = language_of(stage);
  glslang::TShader shader(language);
  const char* chars = text.c_str();
  const int length = static_cast<int>(text.size());
  const char* names[] = {name.c_str()};
  shader.setStringsWithLengthsAndNames(&chars, &length, names, 1);
  const EShMessages messages = hlsl_environment(shader, language);
  const LocationMap by_name = [&](int, int line) { return std::pair<std::string, int>{name, line}; };
  return preprocess(shader, messages, by_name, name);
}

void throw_unless_preprocessed(const Preprocessed& p) {
  if (p.ok) return;
  for (const Diagnostic& d : p.diagnostics)
    if (d.severity == "error") throw Error(d.str(), ExitCode::failed);
  throw Error(p.diagnostics.empty() ? "glslang could not preprocess it" : p.diagnostics.front().str(), ExitCode::failed);
}

}  // namespace pn
