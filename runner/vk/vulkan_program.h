// What the Vulkan executor's compute and raster programs share: shader modules, the set layout
// from their SPIR-V's own reflection, the pipeline layout, and a dispatch's or draw's descriptor set.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "device/query_device.h"
#include "shader/spirv_cross.h"
#include "vk/vulkan_device.h"
#include "vk/vulkan_resources.h"

namespace pn::vk {

// The storage buffer of the loop guard (shader/loop_guard.h) on Vulkan: below the HLSL samplers'
// shifted bindings, above every pass's own.
constexpr unsigned kGuardBinding = kHlslSamplerBindingShift - 1;

// The resources of one dispatch or draw in a descriptor set of its own (a pool a set), with the
// uniform block's buffer and the loop guard's.
struct BoundSet {
  const VulkanDevice::State* s = nullptr;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
  std::list<HostBuffer> uniforms;  // one a uniform block
  std::optional<HostBuffer> guard;
  BoundSet() = default;
  BoundSet(const BoundSet&) = delete;
  BoundSet& operator=(const BoundSet&) = delete;
  ~BoundSet();
};

// What a compute and a raster program share: a name, the resources its SPIR-V uses (every stage's),
// their set layout, the pipeline layout and the pipeline.
class VulkanProgram : public QueryProgram {
 public:
  ~VulkanProgram() override;

 protected:
  // `stages`: each stage's SPIR-V and its stage bit; a resource two stages use is one binding.
  VulkanProgram(const VulkanDevice::State& s, std::string name,
                const std::vector<std::pair<const std::vector<std::uint32_t>*, VkShaderStageFlagBits>>& stages);

  // A descriptor set holding `resources` at the bindings the SPIR-V uses (and the loop guard's
  // buffer, cleared, where it has one). Throws Error naming a resource it uses and `resources`
  // lacks, or one made on another device.
  void bind(const PassResources& resources, BoundSet& out) const;
  // The binding of `b`'s resource in a dispatch's PassResources: the GLSL binding, which under
  // --api hlsl is the register less the plan's shift (the sampler shift stays on samplers alone).
  unsigned resource_binding(const SpirvBinding& b) const;
  // Binds `bound` (when it holds a set) at the set the SPIR-V names.
  void bind_set(VkCommandBuffer c, VkPipelineBindPoint point, const BoundSet& bound) const;

  template <class Made>
  const Made& made_here(const auto& object, unsigned binding) const {
    const auto* made = dynamic_cast<const Made*>(&object);
    if (made == nullptr || made->owner() != s_)
      throw Error(name_ + ": the resource at binding " + std::to_string(binding) + " was made on another device",
                  ExitCode::failed);
    return *made;
  }

  const VulkanDevice::State* s_;
  std::string name_;
  std::vector<SpirvBinding> bindings_;
  std::vector<VkShaderModule> modules_;
  unsigned local_size_[3] = {1, 1, 1};
  unsigned set_index_ = 0;  // 0 but for an HLSL export written in a register space
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout empty_layout_ = VK_NULL_HANDLE;  // the sets below set_index_
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace pn::vk
