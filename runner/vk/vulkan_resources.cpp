#include "vk/vulkan_resources.h"

#include <algorithm>
#include <cstring>
#include <optional>
#include <utility>

#include "core/error.h"
#include "vk/vulkan_pipeline_parts.h"
#include "vk/vulkan_state.h"

// Vulkan's create-info structs are named by their sType and then filled field by field.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace pn::vk {

HostBuffer::HostBuffer(const VulkanDevice::State& s, VkDeviceSize size, VkBufferUsageFlags usage)
    : s_(&s), size_(size) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = std::max<VkDeviceSize>(size, 4);
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  vk_check(vkCreateBuffer(s.device, &info, nullptr, &buffer_), "creating a buffer");
  VkMemoryRequirements needs;
  vkGetBufferMemoryRequirements(s.device, buffer_, &needs);
  VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocate.allocationSize = needs.size;
  allocate.memoryTypeIndex =
      s.memory_type(needs.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  vk_check(vkAllocateMemory(s.device, &allocate, nullptr, &memory_), "allocating buffer memory");
  vk_check(vkBindBufferMemory(s.device, buffer_, memory_, 0), "binding buffer memory");
  vk_check(vkMapMemory(s.device, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "mapping a buffer");
}

HostBuffer::~HostBuffer() {
  if (s_->abandoned()) return;  // a stuck job may read it (State)
  if (memory_ != VK_NULL_HANDLE) vkFreeMemory(s_->device, memory_, nullptr);  // unmaps
  if (buffer_ != VK_NULL_HANDLE) vkDestroyBuffer(s_->device, buffer_, nullptr);
}

VkDeviceMemory bind_image_memory(const VulkanDevice::State& s, VkImage image, const std::string& what) {
  VkMemoryRequirements needs;
  vkGetImageMemoryRequirements(s.device, image, &needs);
  VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocate.allocationSize = needs.size;
  allocate.memoryTypeIndex = s.memory_type(needs.memoryTypeBits, 0);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  vk_check(vkAllocateMemory(s.device, &allocate, nullptr, &memory), "allocating " + what);
  const VkResult bound = vkBindImageMemory(s.device, image, memory, 0);
  if (bound != VK_SUCCESS) vkFreeMemory(s.device, memory, nullptr);
  vk_check(bound, "binding " + what);
  return memory;
}

void image_barrier(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                   VkAccessFlags src_access, VkAccessFlags dst_access, VkPipelineStageFlags src_stage,
                   VkPipelineStageFlags dst_stage) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcAccessMask = src_access;
  barrier.dstAccessMask = dst_access;
  barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
  vkCmdPipelineBarrier(commands, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

VkFormat vk_format(TexelFormat format) {
  switch (format) {
    case TexelFormat::r32f: return VK_FORMAT_R32_SFLOAT;
    case TexelFormat::rg32f: return VK_FORMAT_R32G32_SFLOAT;
    case TexelFormat::rgba32f: return VK_FORMAT_R32G32B32A32_SFLOAT;
    case TexelFormat::rgba32ui: return VK_FORMAT_R32G32B32A32_UINT;
  }
  return VK_FORMAT_R32G32B32A32_SFLOAT;
}

std::string shape_text(const TextureShape& shape) {
  return std::to_string(shape.width) + "x" + std::to_string(shape.height) + " (" + std::to_string(shape.levels) +
         " levels, " + std::to_string(shape.layers) + " layers)";
}

VulkanImage::VulkanImage(const VulkanDevice::State& s, const TextureShape& shape) : DeviceTexture(shape), s_(&s) {
  const VkFormat format = vk_format(shape.format);
  VkImageFormatProperties limits{};
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                  VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                  VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  const VkResult supported = vkGetPhysicalDeviceImageFormatProperties(
      s.physical, format, VK_IMAGE_TYPE_2D, VK_IMAGE_TILING_OPTIMAL, usage, 0, &limits);
  int full_levels = 1;
  while ((std::max(shape.width, shape.height) >> full_levels) > 0) ++full_levels;
  if (supported != VK_SUCCESS || shape.width < 1 || shape.height < 1 ||
      static_cast<uint32_t>(shape.width) > limits.maxExtent.width ||
      static_cast<uint32_t>(shape.height) > limits.maxExtent.height || shape.layers < 1 ||
      static_cast<uint32_t>(shape.layers) > limits.maxArrayLayers || (shape.layers > 1 && !shape.array) ||
      shape.levels < 1 || shape.levels > full_levels)
    throw Error("vulkan: a texture of " + shape_text(shape) + ": expected sides 1.." +
                    std::to_string(limits.maxExtent.width) + ", 1.." + std::to_string(limits.maxArrayLayers) +
                    " layers (an array for more than one), 1.." + std::to_string(full_levels) +
                    " levels, and a format the device samples and stores",
                ExitCode::failed);
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {static_cast<uint32_t>(shape.width), static_cast<uint32_t>(shape.height), 1};
  info.mipLevels = static_cast<uint32_t>(shape.levels);
  info.arrayLayers = static_cast<uint32_t>(shape.layers);
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  vk_check(vkCreateImage(s.device, &info, nullptr, &image_), "creating a " + shape_text(shape) + " image");
  memory_ = bind_image_memory(s, image_, "image memory");
  view_ = make_view(0, shape.levels);
  for (int level = 0; level < shape.levels; ++level) level_views_.push_back(make_view(level, 1));
}

VulkanImage::~VulkanImage() {
  if (s_->abandoned()) return;  // a stuck job may read it (State)
  for (VkImageView view : level_views_) vkDestroyImageView(s_->device, view, nullptr);
  if (view_ != VK_NULL_HANDLE) vkDestroyImageView(s_->device, view_, nullptr);
  if (image_ != VK_NULL_HANDLE) vkDestroyImage(s_->device, image_, nullptr);
  if (memory_ != VK_NULL_HANDLE) vkFreeMemory(s_->device, memory_, nullptr);
}

void VulkanImage::fill(const void* bytes, std::size_t size) const {
  const std::optional<HostBuffer> staging =
      bytes ? std::optional<HostBuffer>(std::in_place, *s_, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT) : std::nullopt;
  if (staging) std::memcpy(staging->data(), bytes, size);
  s_->submit("uploading an image", [&](VkCommandBuffer c) {
    image_barrier(c, image_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                  VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    if (staging) {
      const VkBufferImageCopy copy = region(0, 0);
      vkCmdCopyBufferToImage(c, staging->buffer(), image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
    } else {
      const VkClearColorValue zero{};
      const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0,
                                          VK_REMAINING_ARRAY_LAYERS};
      vkCmdClearColorImage(c, image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
    }
    image_barrier(c, image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kImageLayout, VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  });
}

std::vector<std::uint32_t> VulkanImage::read(int level, int layer) const {
  const TextureShape& shape = this->shape();
  if (level < 0 || level >= shape.levels || layer < 0 || layer >= shape.layers)
    throw Error("vulkan: reading level " + std::to_string(level) + ", layer " + std::to_string(layer) +
                    " of a texture of " + shape_text(shape),
                ExitCode::failed);
  const std::size_t words = static_cast<std::size_t>(shape.level_width(level)) * shape.level_height(level) *
                            static_cast<std::size_t>(texel_channels(shape.format));
  const HostBuffer staging(*s_, words * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  s_->submit("reading a texture back", [&](VkCommandBuffer c) {
    image_barrier(c, image_, kImageLayout, kImageLayout, VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT,
                  VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    const VkBufferImageCopy copy = region(level, layer);
    vkCmdCopyImageToBuffer(c, image_, kImageLayout, staging.buffer(), 1, &copy);
    VkMemoryBarrier host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &host, 0, nullptr, 0,
                         nullptr);
  });
  std::vector<std::uint32_t> out(words);
  std::memcpy(out.data(), staging.data(), words * 4);
  return out;
}

VkImageView VulkanImage::make_view(int first_level, int levels) const {
  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = image_;
  view.viewType = shape().array ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
  view.format = vk_format(shape().format);
  view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, static_cast<uint32_t>(first_level),
                           static_cast<uint32_t>(levels), 0, static_cast<uint32_t>(shape().layers)};
  VkImageView out = VK_NULL_HANDLE;
  vk_check(vkCreateImageView(s_->device, &view, nullptr, &out), "creating an image view");
  return out;
}

VkBufferImageCopy VulkanImage::region(int level, int layer) const {
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, static_cast<uint32_t>(level), static_cast<uint32_t>(layer), 1};
  copy.imageExtent = {static_cast<uint32_t>(shape().level_width(level)),
                      static_cast<uint32_t>(shape().level_height(level)), 1};
  return copy;
}

std::unique_ptr<VulkanImage> upload_image(const VulkanDevice::State& s, const Image& image) {
  if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4)
    throw Error("vulkan: an image of " + std::to_string(image.width) + "x" + std::to_string(image.height) + "x" +
                    std::to_string(image.channels) + ": expected a positive size and 1 to 4 channels",
                ExitCode::failed);
  // 3 channels go up as 4, alpha 1 (GL's RGB32F reads).
  const TextureShape shape = float_shape(image.width, image.height, image.channels);
  const int channels = texel_channels(shape.format);
  std::vector<float> texels(static_cast<std::size_t>(image.width) * image.height * channels, 1.0f);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < image.channels; ++c)
        texels[(static_cast<std::size_t>(y) * image.width + x) * channels + c] = image.at(x, y, c);
  auto out = std::make_unique<VulkanImage>(s, shape);
  out->fill(texels.data(), texels.size() * sizeof(float));
  return out;
}

Image float_image(const std::vector<std::uint32_t>& words, int width, int height, int channels) {
  Image image(width, height, channels);
  std::memcpy(image.texels.data(), words.data(), words.size() * 4);
  return image;
}

}  // namespace pn::vk
