// What every Vulkan pipeline here is built from, shared by the executor (vk/vulkan_program.cpp) and
// `penumbra isa`'s null device (isa/radv_null.cpp): a call's result checked, a shader module, and
// the one descriptor set a pipeline's stages need, from their SPIR-V's own reflection.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "shader/spirv_cross.h"

namespace pn {

// Throws Error(ExitCode::failed) "vulkan: WHAT failed (VkResult N)" unless `result` is VK_SUCCESS.
void vk_check(VkResult result, const std::string& what);

VkDescriptorType descriptor_type(DescriptorKind kind);

// `name`: the pass, for the error. Throws as vk_check.
VkShaderModule make_shader_module(VkDevice device, const std::vector<std::uint32_t>& spirv, const std::string& name);

// The one descriptor set of a pipeline: every stage's resources (those it uses), a binding two
// stages use one entry with both stage bits, and the compute stage's work group size. The set is 0
// but for an HLSL export written with a register space (shader/register_plan.h).
struct SetLayoutBindings {
  std::vector<SpirvBinding> bindings;              // the reflection's, one a binding number
  std::vector<VkDescriptorSetLayoutBinding> layout;  // the same order
  unsigned set = 0;
  unsigned local_size[3] = {1, 1, 1};
};
// Throws Error(ExitCode::failed) naming `name` for resources in two sets, or one binding number of
// two kinds (two stages' resources, or two of one stage's that a register plan put together).
SetLayoutBindings set_layout_bindings(
    const std::vector<std::pair<const std::vector<std::uint32_t>*, VkShaderStageFlagBits>>& stages,
    const std::string& name);

}  // namespace pn
