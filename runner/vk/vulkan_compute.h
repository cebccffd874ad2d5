// The Vulkan executor's compute side: a query batch (its inputs uploaded, its result images) and
// a compute program, dispatched over a grid or over group counts a pass wrote, under the loop guard.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "device/query_device.h"
#include "shader/loop_guard.h"
#include "vk/vulkan_device.h"
#include "vk/vulkan_program.h"
#include "vk/vulkan_resources.h"

namespace pn::vk {

class VulkanQueryBatch final : public QueryBatch {
 public:
  VulkanQueryBatch(const VulkanDevice::State& s, const std::vector<Image>& inputs, std::size_t results,
                   std::size_t word_results);
  int width() const override { return width_; }
  int height() const override { return height_; }
  std::size_t inputs() const override { return inputs_.size(); }
  std::size_t results() const override { return results_.size(); }
  std::size_t word_results() const override { return word_results_.size(); }
  QueryResults read() const override;

  std::vector<std::unique_ptr<VulkanImage>> inputs_, results_, word_results_;

 private:
  int width_ = 0, height_ = 0;
};

class VulkanQueryProgram final : public VulkanProgram {
 public:
  VulkanQueryProgram(const VulkanDevice::State& s, std::string name, const std::vector<std::uint32_t>& spirv,
                     std::vector<GuardedLoop> loops);

  // Binds `resources` (the loop guard besides, under bounds) and runs the pass over a width ×
  // height grid of invocations, or (`groups`) over the work groups counted in that buffer.
  void run(const PassResources& resources, int width, int height, const DispatchBounds& bounds,
           const HostBuffer* groups = nullptr) const;

 private:
  std::vector<GuardedLoop> loops_;
};

}  // namespace pn::vk
