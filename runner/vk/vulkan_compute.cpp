#include "vk/vulkan_compute.h"

#include <cstring>
#include <tuple>
#include <utility>

#include "core/error.h"
#include "vk/vulkan_pipeline_parts.h"
#include "vk/vulkan_state.h"

// Vulkan's create-info structs are named by their sType and then filled field by field.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace pn::vk {

VulkanQueryBatch::VulkanQueryBatch(const VulkanDevice::State& s, const std::vector<Image>& inputs,
                                   std::size_t results, std::size_t word_results) {
  std::tie(width_, height_) = query_batch_size(inputs);
  for (const Image& input : inputs) inputs_.push_back(upload_image(s, input));
  for (std::size_t i = 0; i < results + word_results; ++i) {
    const TexelFormat format = i < results ? TexelFormat::rgba32f : TexelFormat::rgba32ui;
    auto image = std::make_unique<VulkanImage>(s, TextureShape{format, width_, height_});
    image->fill(nullptr, 0);
    (i < results ? results_ : word_results_).push_back(std::move(image));
  }
}

QueryResults VulkanQueryBatch::read() const {
  QueryResults out;
  for (const auto& result : results_) out.images.push_back(float_image(result->read(0, 0), width_, height_, 4));
  for (const auto& result : word_results_) out.words.push_back(result->read(0, 0));
  return out;
}

VulkanQueryProgram::VulkanQueryProgram(const VulkanDevice::State& s, std::string name,
                                       const std::vector<std::uint32_t>& spirv, std::vector<GuardedLoop> loops)
    : VulkanProgram(s, std::move(name), {{&spirv, VK_SHADER_STAGE_COMPUTE_BIT}}), loops_(std::move(loops)) {
  VkComputePipelineCreateInfo pipeline_info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  pipeline_info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  pipeline_info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  pipeline_info.stage.module = modules_.front();
  pipeline_info.stage.pName = "main";
  pipeline_info.layout = pipeline_layout_;
  vk_check(vkCreateComputePipelines(s.device, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, &pipeline_),
           name_ + ": a compute pipeline");
  s.throw_if_messages(name_);
}

void VulkanQueryProgram::run(const PassResources& resources, int width, int height, const DispatchBounds& bounds,
                             const HostBuffer* groups) const {
  if (groups == nullptr && (width <= 0 || height <= 0)) return;
  const VulkanDevice::State& s = *s_;
  BoundSet bound;
  bind(resources, bound);
  const auto group_count = [](int n, unsigned local) { return static_cast<uint32_t>((n + local - 1) / local); };
  s.submit(name_ + ": dispatch", [&](VkCommandBuffer c) {
    VkMemoryBarrier before{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    before.srcAccessMask = VK_ACCESS_HOST_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    before.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_UNIFORM_READ_BIT |
                           VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
    vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT, 0, 1, &before, 0,
                         nullptr, 0, nullptr);
    vkCmdBindPipeline(c, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    bind_set(c, VK_PIPELINE_BIND_POINT_COMPUTE, bound);
    if (groups != nullptr)
      vkCmdDispatchIndirect(c, groups->buffer(), 0);
    else
      vkCmdDispatch(c, group_count(width, local_size_[0]), group_count(height, local_size_[1]), 1);
    VkMemoryBarrier after{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    after.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    after.dstAccessMask = VK_ACCESS_HOST_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_SHADER_READ_BIT;
    vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         0, 1, &after, 0, nullptr, 0, nullptr);
  });
  if (!bound.guard) return;
  LoopGuardState state;
  std::memcpy(&state, bound.guard->data(), sizeof state);
  throw_if_loop_tripped(state, loops_, bounds.loop_iterations, name_ + ": dispatch");
}

}  // namespace pn::vk
