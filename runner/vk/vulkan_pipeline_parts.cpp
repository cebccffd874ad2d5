#include "vk/vulkan_pipeline_parts.h"

#include <algorithm>
#include <iterator>

#include "core/error.h"

// Vulkan's create-info structs are named by their sType and then filled field by field.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace pn {

void vk_check(VkResult result, const std::string& what) {
  if (result != VK_SUCCESS)
    throw Error("vulkan: " + what + " failed (VkResult " + std::to_string(static_cast<int>(result)) + ")",
                ExitCode::failed);
}

VkDescriptorType descriptor_type(DescriptorKind kind) {
  switch (kind) {
    case DescriptorKind::combined_image_sampler: return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    case DescriptorKind::sampled_image: return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    case DescriptorKind::sampler: return VK_DESCRIPTOR_TYPE_SAMPLER;
    case DescriptorKind::storage_image: return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    case DescriptorKind::uniform_buffer: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case DescriptorKind::storage_buffer: return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  }
  return VK_DESCRIPTOR_TYPE_MAX_ENUM;
}

VkShaderModule make_shader_module(VkDevice device, const std::vector<std::uint32_t>& spirv, const std::string& name) {
  VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  module_info.codeSize = spirv.size() * sizeof(std::uint32_t);
  module_info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  vk_check(vkCreateShaderModule(device, &module_info, nullptr, &module), name + ": a shader module");
  return module;
}

SetLayoutBindings set_layout_bindings(
    const std::vector<std::pair<const std::vector<std::uint32_t>*, VkShaderStageFlagBits>>& stages,
    const std::string& name) {
  SetLayoutBindings out;
  for (const auto& [spirv, stage] : stages) {
    const SpirvReflection reflection = reflect_spirv(*spirv, true);
    if (stage == VK_SHADER_STAGE_COMPUTE_BIT)
      std::copy(std::begin(reflection.local_size), std::end(reflection.local_size), out.local_size);
    for (const SpirvBinding& b : reflection.bindings) {
      if (!out.bindings.empty() && b.set != out.set)
        throw Error(name + ": '" + b.name + "' is in descriptor set " + std::to_string(b.set) + ", '" +
                        out.bindings.front().name + "' in set " + std::to_string(out.set) + ": expected one set",
                    ExitCode::failed);
      out.set = b.set;
      const auto same = std::find_if(out.bindings.begin(), out.bindings.end(),
                                     [&](const SpirvBinding& known) { return known.binding == b.binding; });
      if (same != out.bindings.end()) {
        const auto before = reflection.bindings.begin() + (&b - reflection.bindings.data());
        const bool this_stage = std::any_of(reflection.bindings.begin(), before,
                                            [&](const SpirvBinding& earlier) { return earlier.binding == b.binding; });
        if (same->kind != b.kind || this_stage)
          throw Error(name + ": binding " + std::to_string(b.binding) + " is both '" + same->name + "' and '" + b.name +
                          "' (Vulkan has one binding namespace a set: a register plan must keep them apart)",
                      ExitCode::failed);
        out.layout[static_cast<std::size_t>(same - out.bindings.begin())].stageFlags |= stage;
        continue;
      }
      out.bindings.push_back(b);
      out.layout.push_back({b.binding, descriptor_type(b.kind), 1, static_cast<VkShaderStageFlags>(stage), nullptr});
    }
  }
  return out;
}

}  // namespace pn
