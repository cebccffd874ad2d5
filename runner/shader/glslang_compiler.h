// glslang as the reference front end: compiles a ShaderSource, for its stage
// (compute, vertex or fragment), for one Target. GL 4.50 and ES 3.10 are parsed as glslangValidator
// does without -V (client none: ordinary GLSL, as drivers see it); Vulkan is
// parsed with Vulkan rules, translated to SPIR-V and validated by SPIRV-Tools.
#pragma once

#include <cstdint>
#include <vector>

#include "shader/diagnostic.h"
#include "shader/target.h"

namespace pn {

// glslang's process-wide tables live as long as one of these does.
class GlslangProcess {
 public:
  GlslangProcess();
  ~GlslangProcess();
  GlslangProcess(const GlslangProcess&) = delete;
  GlslangProcess& operator=(const GlslangProcess&) = delete;
};

struct CompileResult {
  bool ok = false;
  std::vector<Diagnostic> diagnostics;  // file names are the ShaderSource's table entries
  std::vector<uint32_t> spirv;          // Vulkan target only
};

CompileResult compile_with_glslang(const GlslangProcess& process, const ShaderSource& source, Target target);

// The first error of `result` as "file:line: error: message", or `fallback` when it has none.
std::string first_error(const CompileResult& result, const std::string& fallback);

// glslang's preprocessor output (glslangValidator -E) for `source` as compile_with_glslang
// reads it for `target`, or for an HLSL text: macros expanded, comments and line continuations
// gone, directives other than #version, #extension, #pragma and #line consumed. Each token stays
// on its line (a #line marker is passed on as written), so the text maps back as the input did.
// The loop guard reads this (shader/loop_guard.h): what the compiler will see.
struct Preprocessed {
  bool ok = false;
  std::vector<Diagnostic> diagnostics;  // as CompileResult's
  std::string text;
};

Preprocessed preprocess_with_glslang(const GlslangProcess& process, const ShaderSource& source, Target target);
// Throws Error(ExitCode::failed) with the preprocessor's first error unless `p` is ok (the compiler
// would refuse the source with it).
void throw_unless_preprocessed(const Preprocessed& p);
Preprocessed preprocess_hlsl_with_glslang(const GlslangProcess& process, const std::string& text,
                                          const std::string& name, Stage stage);

// HLSL (an export of shader/spirv_cross.h, or an engine's copy of one) through glslang's HLSL
// front end to SPIR-V for Vulkan 1.0, validated: entry point `main`, register t<N>/u<N>/b<N> at
// binding N and s<N> at N + kHlslSamplerBindingShift. `name` is the file diagnostics name.
CompileResult compile_hlsl_with_glslang(const GlslangProcess& process, const std::string& text,
                                        const std::string& name, Stage stage);

}  // namespace pn
