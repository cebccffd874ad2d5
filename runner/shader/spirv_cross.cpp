#include "shader/spirv_cross.h"

#include <spirv_cross/spirv_cross_c.h>

#include <algorithm>
#include <memory>

#include "core/error.h"
#include "shader/register_plan.h"

namespace pn {

namespace {

// One SPIRV-Cross context, destroyed with everything it made; its last error kept for the message.
class CrossContext {
 public:
  CrossContext() {
    if (spvc_context_create(&context_) != SPVC_SUCCESS) throw Error("SPIRV-Cross: no context", ExitCode::failed);
    spvc_context_set_error_callback(
        context_, [](void* self, const char* message) { static_cast<CrossContext*>(self)->error_ = message; }, this);
  }
  ~CrossContext() { spvc_context_destroy(context_); }
  CrossContext(const CrossContext&) = delete;
  CrossContext& operator=(const CrossContext&) = delete;

  spvc_compiler compiler(const std::vector<std::uint32_t>& spirv, spvc_backend backend) {
    spvc_parsed_ir ir = nullptr;
    spvc_compiler compiler = nullptr;
    check(spvc_context_parse_spirv(context_, spirv.data(), spirv.size(), &ir), "parsing SPIR-V");
    check(spvc_context_create_compiler(context_, backend, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &compiler),
          "making a compiler");
    return compiler;
  }
  void check(spvc_result result, const std::string& what) const {
    if (result != SPVC_SUCCESS) throw Error("SPIRV-Cross: " + what + ": " + error_, ExitCode::failed);
  }

 private:
  spvc_context context_ = nullptr;
  std::string error_;
};

// GLSL's name of a storage image format (the ones the passes declare, and their kin).
std::string image_format_name(SpvImageFormat format) {
  switch (format) {
    case SpvImageFormatRgba32f: return "rgba32f";
    case SpvImageFormatRg32f: return "rg32f";
    case SpvImageFormatR32f: return "r32f";
    case SpvImageFormatRgba16f: return "rgba16f";
    case SpvImageFormatRg16f: return "rg16f";
    case SpvImageFormatR16f: return "r16f";
    case SpvImageFormatRgba8: return "rgba8";
    case SpvImageFormatRgba32ui: return "rgba32ui";
    case SpvImageFormatRg32ui: return "rg32ui";
    case SpvImageFormatR32ui: return "r32ui";
    case SpvImageFormatRgba32i: return "rgba32i";
    case SpvImageFormatR32i: return "r32i";
    default: return "";
  }
}

}  // namespace

SpirvReflection reflect_spirv(const std::vector<std::uint32_t>& spirv, bool active_only) {
  CrossContext context;
  spvc_compiler compiler = context.compiler(spirv, SPVC_BACKEND_NONE);
  spvc_resources resources = nullptr;
  if (active_only) {
    spvc_set active = nullptr;
    context.check(spvc_compiler_get_active_interface_variables(compiler, &active), "finding the used resources");
    context.check(spvc_compiler_create_shader_resources_for_active_variables(compiler, &resources, active),
                  "reflecting resources");
  } else {
    context.check(spvc_compiler_create_shader_resources(compiler, &resources), "reflecting resources");
  }
  SpirvReflection out;
  const std::pair<spvc_resource_type, DescriptorKind> kinds[] = {
      {SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, DescriptorKind::combined_image_sampler},
      {SPVC_RESOURCE_TYPE_SEPARATE_IMAGE, DescriptorKind::sampled_image},
      {SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS, DescriptorKind::sampler},
      {SPVC_RESOURCE_TYPE_STORAGE_IMAGE, DescriptorKind::storage_image},
      {SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, DescriptorKind::uniform_buffer},
      {SPVC_RESOURCE_TYPE_STORAGE_BUFFER, DescriptorKind::storage_buffer}};
  for (const auto& [type, kind] : kinds) {
    const spvc_reflected_resource* list = nullptr;
    size_t count = 0;
    context.check(spvc_resources_get_resource_list_for_type(resources, type, &list, &count), "listing resources");
    for (size_t i = 0; i < count; ++i) {
      SpirvBinding b;
      b.set = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationDescriptorSet);
      b.binding = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationBinding);
      b.kind = kind;
      b.name = list[i].name;
      if (kind == DescriptorKind::storage_image) {
        const spvc_type image = spvc_compiler_get_type_handle(compiler, list[i].type_id);
        const spvc_type sampled = spvc_compiler_get_type_handle(compiler, spvc_type_get_image_sampled_type(image));
        const spvc_basetype base = spvc_type_get_basetype(sampled);
        b.integer = base == SPVC_BASETYPE_UINT32 || base == SPVC_BASETYPE_INT32;
        b.format = image_format_name(spvc_type_get_image_storage_format(image));
      }
      b.non_writable = spvc_compiler_has_decoration(compiler, list[i].id, SpvDecorationNonWritable);
      if (kind == DescriptorKind::storage_buffer && !b.non_writable) {
        // A buffer's readonly (GLSL's, HLSL's ByteAddressBuffer) is on its block's members.
        const spvc_type block = spvc_compiler_get_type_handle(compiler, list[i].base_type_id);
        const unsigned members = spvc_type_get_num_member_types(block);
        bool all = members > 0;
        for (unsigned m = 0; all && m < members; ++m)
          all = spvc_compiler_has_member_decoration(compiler, list[i].base_type_id, m, SpvDecorationNonWritable);
        b.non_writable = all;
      }
      b.non_readable = spvc_compiler_has_decoration(compiler, list[i].id, SpvDecorationNonReadable);
      out.bindings.push_back(b);
    }
  }
  for (unsigned axis = 0; axis < 3; ++axis)
    out.local_size[axis] =
        std::max(1u, spvc_compiler_get_execution_mode_argument_by_index(compiler, SpvExecutionModeLocalSize, axis));
  return out;
}

namespace {

const char* kind_name(DescriptorKind kind) {
  switch (kind) {
    case DescriptorKind::combined_image_sampler: return "sampler";
    case DescriptorKind::sampled_image: return "texture";
    case DescriptorKind::sampler: return "sampler state";
    case DescriptorKind::storage_image: return "image";
    case DescriptorKind::uniform_buffer: return "uniform block";
    case DescriptorKind::storage_buffer: return "storage buffer";
  }
  return "?";
}

}  // namespace

std::vector<std::string> shared_bindings(const SpirvReflection& reflection) {
  std::vector<std::string> out;
  const auto& all = reflection.bindings;
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j)
      if (all[i].set == all[j].set && all[i].binding == all[j].binding)
        out.push_back("binding " + std::to_string(all[i].binding) + " of set " + std::to_string(all[i].set) + ": '" +
                      all[i].name + "' (" + kind_name(all[i].kind) + ") and '" + all[j].name + "' (" +
                      kind_name(all[j].kind) + ")");
  return out;
}

const char* cross_language_name(CrossLanguage language) {
  switch (language) {
    case CrossLanguage::hlsl50: return "HLSL shader model 5.0";
    case CrossLanguage::hlsl51: return "HLSL shader model 5.1";
    case CrossLanguage::hlsl60: return "HLSL shader model 6.0";
    case CrossLanguage::msl: return "MSL 2.0";
  }
  return "?";
}

std::string cross_compile(const std::vector<std::uint32_t>& spirv, CrossLanguage language, const RegisterPlan& plan) {
  CrossContext context;
  const bool msl = language == CrossLanguage::msl;
  if (msl && !plan.identity()) throw Error("a register plan applies to HLSL only, not MSL", ExitCode::failed);
  if (language == CrossLanguage::hlsl50 && plan.space != 0)
    throw Error("a register space needs HLSL shader model 5.1 or later", ExitCode::failed);
  spvc_compiler compiler = context.compiler(spirv, msl ? SPVC_BACKEND_MSL : SPVC_BACKEND_HLSL);
  spvc_compiler_options options = nullptr;
  context.check(spvc_compiler_create_compiler_options(compiler, &options), "options");
  SpvExecutionModel model = SpvExecutionModelGLCompute;
  const spvc_entry_point* entries = nullptr;
  size_t entry_count = 0;
  context.check(spvc_compiler_get_entry_points(compiler, &entries, &entry_count), "listing entry points");
  if (entry_count > 0) model = entries[0].execution_model;
  if (msl) {
    context.check(spvc_compiler_options_set_uint(options, SPVC_COMPILER_OPTION_MSL_VERSION, 20000), "MSL version");
    // [[texture(N)]], [[sampler(N)]], [[buffer(N)]] at the GLSL binding N, as HLSL's registers are.
    for (const SpirvBinding& b : reflect_spirv(spirv).bindings) {
      spvc_msl_resource_binding binding;
      spvc_msl_resource_binding_init(&binding);
      binding.stage = model;
      binding.desc_set = b.set;
      binding.binding = b.binding;
      binding.msl_buffer = binding.msl_texture = binding.msl_sampler = b.binding;
      context.check(spvc_compiler_msl_add_resource_binding(compiler, &binding), "an MSL binding");
    }
  } else {
    context.check(spvc_compiler_options_set_uint(options, SPVC_COMPILER_OPTION_HLSL_SHADER_MODEL,
                                                 language == CrossLanguage::hlsl60   ? 60
                                                 : language == CrossLanguage::hlsl51 ? 51
                                                                                     : 50),
                  "shader model");
    // The plan's registers: binding N's t, s, u or b register at N + that kind's shift, in its space.
    if (!plan.identity())
      for (const SpirvBinding& b : reflect_spirv(spirv).bindings) {
        spvc_hlsl_resource_binding binding;
        spvc_hlsl_resource_binding_init(&binding);
        binding.stage = model;
        binding.desc_set = b.set;
        binding.binding = b.binding;
        binding.srv = {plan.space, b.binding + plan.t};
        binding.sampler = {plan.space, b.binding + plan.s};
        binding.uav = {plan.space, b.binding + plan.u};
        binding.cbv = {plan.space, b.binding + plan.b};
        context.check(spvc_compiler_hlsl_add_resource_binding(compiler, &binding), "an HLSL register");
      }
  }
  context.check(spvc_compiler_install_compiler_options(compiler, options), "options");
  const char* source = nullptr;
  context.check(spvc_compiler_compile(compiler, &source), std::string("writing ") + cross_language_name(language));
  return source;
}

}  // namespace pn
