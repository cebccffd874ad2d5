// SPIRV-Cross (its C API, Debian's libspirv-cross-c-shared) on the SPIR-V the vulkan target
// makes: what a module's entry declares — each resource's binding and kind, the work group size —
// for an executor to bind (vk/), and the same entry written as HLSL (shader model 5.0 or 6.0) or
// MSL for an engine to take (`penumbra bundle --target hlsl|msl`, docs/integration.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pn {

// The kinds of descriptor the passes declare. GLSL for Vulkan keeps samplers combined with their
// images; HLSL has no combined sampler, so SPIRV-Cross splits each into a texture (t register)
// and a sampler (s register), which come back from glslang's HLSL front end as separate ones.
enum class DescriptorKind { combined_image_sampler, sampled_image, sampler, storage_image, uniform_buffer, storage_buffer };

struct SpirvBinding {
  unsigned set = 0, binding = 0;
  DescriptorKind kind = DescriptorKind::combined_image_sampler;
  std::string name;
  bool integer = false;  // a storage image of integer texels (rgba32ui)
  std::string format;    // a storage image's declared format ("rgba32f", "r32ui"; "" unknown or not an image)
  bool non_writable = false, non_readable = false;  // GLSL readonly, writeonly (a buffer's: all its members')
};

struct SpirvReflection {
  std::vector<SpirvBinding> bindings;
  unsigned local_size[3] = {1, 1, 1};
};

// Every resource the entry declares, or (`active_only`) those it uses: what a pipeline must bind.
// Throws Error(ExitCode::failed) with SPIRV-Cross's message when it cannot parse `spirv`.
SpirvReflection reflect_spirv(const std::vector<std::uint32_t>& spirv, bool active_only = false);

// One line for each binding number two resources share ("binding 3 of set 0: 'pnCentre'
// (sampler) and 'pnResult' (image)"): legal in GL, whose texture units, image units and buffer
// bindings are apart, but one binding namespace a set in Vulkan. Empty when every number is one's.
std::vector<std::string> shared_bindings(const SpirvReflection& reflection);

enum class CrossLanguage { hlsl50, hlsl51, hlsl60, msl };  // HLSL's register spaces: 5.1 and later
const char* cross_language_name(CrossLanguage language);  // "HLSL shader model 5.0", …

struct RegisterPlan;

// `spirv` as source of `language`; HLSL's registers as `plan` says (shader/register_plan.h; MSL:
// the identity plan only; HLSL 5.0: space 0 only). Throws Error(ExitCode::failed) with SPIRV-Cross's message.
std::string cross_compile(const std::vector<std::uint32_t>& spirv, CrossLanguage language, const RegisterPlan& plan);

// Where an HLSL sampler register s<N> goes when glslang compiles the HLSL back to SPIR-V: binding
// N + kHlslSamplerBindingShift, so that it does not collide with texture t<N> at binding N
// (Vulkan has one binding namespace a set). The Vulkan executor pairs sampler N + shift with
// texture N.
inline constexpr unsigned kHlslSamplerBindingShift = 64;

}  // namespace pn
