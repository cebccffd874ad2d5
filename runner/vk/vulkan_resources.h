// What the Vulkan executor's passes read and write: host-visible buffers (staging, uniform, storage
// buffers), images of levels and layers kept in GENERAL layout, their upload and readback.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/image.h"
#include "device/query_device.h"
#include "vk/vulkan_device.h"

namespace pn::vk {

// A host-visible, coherent buffer, mapped for its life.
class HostBuffer {
 public:
  HostBuffer(const VulkanDevice::State& s, VkDeviceSize size, VkBufferUsageFlags usage);
  ~HostBuffer();
  HostBuffer(const HostBuffer&) = delete;
  HostBuffer& operator=(const HostBuffer&) = delete;
  VkBuffer buffer() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  void* data() const { return mapped_; }

 private:
  const VulkanDevice::State* s_;
  VkDeviceSize size_;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  void* mapped_ = nullptr;
};

// Device-local memory for `image`, bound to it.
VkDeviceMemory bind_image_memory(const VulkanDevice::State& s, VkImage image, const std::string& what);

// Every image stays in GENERAL layout from its upload on: a pass samples one level of a chain while
// it writes the next as a storage image, and results are read back from it.
constexpr VkImageLayout kImageLayout = VK_IMAGE_LAYOUT_GENERAL;

void image_barrier(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                   VkAccessFlags src_access, VkAccessFlags dst_access, VkPipelineStageFlags src_stage,
                   VkPipelineStageFlags dst_stage);

VkFormat vk_format(TexelFormat format);

std::string shape_text(const TextureShape& shape);

// A 2-D image (or 2-D array) of some levels on the device, in GENERAL layout: a view of every
// level and layer to sample, and one a level to write as a storage image.
class VulkanImage final : public DeviceTexture {
 public:
  VulkanImage(const VulkanDevice::State& s, const TextureShape& shape);
  ~VulkanImage() override;
  const VulkanDevice::State* owner() const { return s_; }
  VkImage image() const { return image_; }
  VkImageView view() const { return view_; }                                   // every level and layer
  VkImageView level_view(int level) const { return level_views_[static_cast<size_t>(level)]; }  // every layer
  bool integer() const { return shape().format == TexelFormat::rgba32ui; }

  // Fills level 0 of layer 0 with `bytes` (tightly packed texels of its format), or every texel
  // with zeros, and leaves the image in GENERAL layout.
  void fill(const void* bytes, std::size_t size) const;

  // The texels of one level and layer back, texel_channels(format) words a texel.
  std::vector<std::uint32_t> read(int level, int layer) const;

 private:
  VkImageView make_view(int first_level, int levels) const;
  VkBufferImageCopy region(int level, int layer) const;

  const VulkanDevice::State* s_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  std::vector<VkImageView> level_views_;
};

// A storage buffer: host-visible, so a write is a copy into its mapping.
class VulkanBuffer final : public DeviceBuffer {
 public:
  VulkanBuffer(const VulkanDevice::State& s, std::size_t bytes)
      : buffer_(s, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT), owner_(&s) {}
  const HostBuffer& host() const { return buffer_; }
  const VulkanDevice::State* owner() const { return owner_; }

 private:
  HostBuffer buffer_;
  const VulkanDevice::State* owner_;
};

std::unique_ptr<VulkanImage> upload_image(const VulkanDevice::State& s, const Image& image);

Image float_image(const std::vector<std::uint32_t>& words, int width, int height, int channels);

}  // namespace pn::vk
