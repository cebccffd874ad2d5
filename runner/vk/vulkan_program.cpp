#include "vk/vulkan_program.h"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <vector>

#include "shader/loop_guard.h"
#include "vk/vulkan_pipeline_parts.h"
#include "vk/vulkan_state.h"

// Vulkan's create-info structs are named by their sType and then filled field by field.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace pn::vk {

BoundSet::~BoundSet() {
  if (s == nullptr || s->abandoned()) return;  // a stuck job may read it (State)
  if (pool != VK_NULL_HANDLE) vkDestroyDescriptorPool(s->device, pool, nullptr);
}

VulkanProgram::VulkanProgram(
    const VulkanDevice::State& s, std::string name,
    const std::vector<std::pair<const std::vector<std::uint32_t>*, VkShaderStageFlagBits>>& stages)
    : s_(&s), name_(std::move(name)) {
  for (const auto& [spirv, stage] : stages) modules_.push_back(make_shader_module(s.device, *spirv, name_));
  SetLayoutBindings set = set_layout_bindings(stages, name_);
  bindings_ = std::move(set.bindings);
  std::copy(std::begin(set.local_size), std::end(set.local_size), local_size_);
  const std::vector<VkDescriptorSetLayoutBinding>& layout = set.layout;
  VkDescriptorSetLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  layout_info.bindingCount = static_cast<uint32_t>(layout.size());
  layout_info.pBindings = layout.data();
  vk_check(vkCreateDescriptorSetLayout(s.device, &layout_info, nullptr, &set_layout_), name_ + ": a set layout");
  // An export in register space N: its set is N, the sets below it empty (an engine's own).
  set_index_ = set.set;
  std::vector<VkDescriptorSetLayout> layouts(set_index_ + 1, set_layout_);
  if (set_index_ > 0) {
    VkDescriptorSetLayoutCreateInfo empty{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    vk_check(vkCreateDescriptorSetLayout(s.device, &empty, nullptr, &empty_layout_), name_ + ": an empty set layout");
    std::fill(layouts.begin(), layouts.end() - 1, empty_layout_);
  }
  VkPipelineLayoutCreateInfo pipeline_layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pipeline_layout_info.setLayoutCount = static_cast<uint32_t>(layouts.size());
  pipeline_layout_info.pSetLayouts = layouts.data();
  vk_check(vkCreatePipelineLayout(s.device, &pipeline_layout_info, nullptr, &pipeline_layout_),
           name_ + ": a pipeline layout");
}

VulkanProgram::~VulkanProgram() {
  if (s_->abandoned()) return;  // a stuck job may run it (State)
  for (VkShaderModule module : modules_) vkDestroyShaderModule(s_->device, module, nullptr);
  if (pipeline_ != VK_NULL_HANDLE) vkDestroyPipeline(s_->device, pipeline_, nullptr);
  if (pipeline_layout_ != VK_NULL_HANDLE) vkDestroyPipelineLayout(s_->device, pipeline_layout_, nullptr);
  if (set_layout_ != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(s_->device, set_layout_, nullptr);
  if (empty_layout_ != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(s_->device, empty_layout_, nullptr);
}

void VulkanProgram::bind_set(VkCommandBuffer c, VkPipelineBindPoint point, const BoundSet& bound) const {
  if (bound.set != VK_NULL_HANDLE) vkCmdBindDescriptorSets(c, point, pipeline_layout_, set_index_, 1, &bound.set, 0, nullptr);
}

unsigned VulkanProgram::resource_binding(const SpirvBinding& b) const {
  if (s_->settings.language != PassLanguage::hlsl) return b.binding;
  const RegisterPlan& plan = s_->settings.registers;
  return b.binding - plan.shift(plan.register_kind(b.kind, b.non_writable));
}

void VulkanProgram::bind(const PassResources& resources, BoundSet& out) const {
  const VulkanDevice::State& s = *s_;
  out.s = s_;
  std::vector<VkDescriptorPoolSize> sizes;
  for (const SpirvBinding& b : bindings_) sizes.push_back({descriptor_type(b.kind), 1});
  if (sizes.empty()) return;
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = static_cast<uint32_t>(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  vk_check(vkCreateDescriptorPool(s.device, &pool_info, nullptr, &out.pool), name_ + ": a descriptor pool");
  VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocate.descriptorPool = out.pool;
  allocate.descriptorSetCount = 1;
  allocate.pSetLayouts = &set_layout_;
  vk_check(vkAllocateDescriptorSets(s.device, &allocate, &out.set), name_ + ": a descriptor set");

  std::vector<VkDescriptorImageInfo> images(bindings_.size());
  std::vector<VkDescriptorBufferInfo> buffers(bindings_.size());
  std::vector<VkWriteDescriptorSet> writes;
  for (std::size_t i = 0; i < bindings_.size(); ++i) {
    const SpirvBinding& b = bindings_[i];
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = out.set;
    write.dstBinding = b.binding;
    write.descriptorCount = 1;
    write.descriptorType = descriptor_type(b.kind);
    const std::string where = name_ + ": '" + b.name + "' (binding " + std::to_string(b.binding) + ")";
    const unsigned at = resource_binding(b);  // the binding of the resource in `resources`
    switch (b.kind) {
      case DescriptorKind::combined_image_sampler:
      case DescriptorKind::sampled_image: {
        const auto t = std::find_if(resources.textures.begin(), resources.textures.end(),
                                    [&](const QueryTexture& t) { return t.binding == at; });
        if (t == resources.textures.end())
          throw Error(where + " is a texture the dispatch does not give", ExitCode::failed);
        images[i] = {s.sampler, made_here<VulkanImage>(t->texture, b.binding).view(), kImageLayout};
        write.pImageInfo = &images[i];
        break;
      }
      case DescriptorKind::sampler:
        images[i] = {s.sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED};
        write.pImageInfo = &images[i];
        break;
      case DescriptorKind::storage_image: {
        const auto found = std::find_if(resources.images.begin(), resources.images.end(),
                                        [&](const PassImage& image) { return image.binding == at; });
        if (found == resources.images.end())
          throw Error(where + " is an image the dispatch does not give", ExitCode::failed);
        const VulkanImage& image = made_here<VulkanImage>(found->texture, b.binding);
        if (image.integer() != b.integer)
          throw Error(where + " is an image of " + (b.integer ? "integer" : "float") + " texels: the dispatch gives " +
                          (image.integer() ? "RGBA32UI" : "floats"),
                      ExitCode::failed);
        if (found->level < 0 || found->level >= image.shape().levels)
          throw Error(where + ": level " + std::to_string(found->level) + " of a texture of " +
                          std::to_string(image.shape().levels) + " levels",
                      ExitCode::failed);
        images[i] = {VK_NULL_HANDLE, image.level_view(found->level), kImageLayout};
        write.pImageInfo = &images[i];
        break;
      }
      case DescriptorKind::uniform_buffer: {
        const std::vector<QueryBlock> blocks = uniform_blocks(resources);
        const auto block = std::find_if(blocks.begin(), blocks.end(),
                                        [&](const QueryBlock& block) { return block.binding == at; });
        if (block == blocks.end())
          throw Error(where + " is a uniform block the dispatch does not give", ExitCode::failed);
        HostBuffer& uniform = out.uniforms.emplace_back(s, block->size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        std::memcpy(uniform.data(), block->data, block->size);
        buffers[i] = {uniform.buffer(), 0, block->size};
        write.pBufferInfo = &buffers[i];
        break;
      }
      case DescriptorKind::storage_buffer:
        if (at == kGuardBinding) {
          out.guard.emplace(s, sizeof(LoopGuardState), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
          std::memset(out.guard->data(), 0, sizeof(LoopGuardState));
          buffers[i] = {out.guard->buffer(), 0, sizeof(LoopGuardState)};
        } else {
          const auto found = std::find_if(resources.buffers.begin(), resources.buffers.end(),
                                          [&](const PassBuffer& buffer) { return buffer.binding == at; });
          if (found == resources.buffers.end())
            throw Error(where + " is a storage buffer the dispatch does not give", ExitCode::failed);
          const HostBuffer& buffer = made_here<VulkanBuffer>(found->buffer, b.binding).host();
          buffers[i] = {buffer.buffer(), 0, VK_WHOLE_SIZE};
        }
        write.pBufferInfo = &buffers[i];
        break;
    }
    writes.push_back(write);
  }
  vkUpdateDescriptorSets(s.device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

}  // namespace pn::vk
