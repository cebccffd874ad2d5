// The Vulkan plumbing the example needs, and nothing more: an instance (with the Khronos
// validation layer when it is installed, every message of it counted), the first device with a
// compute-and-graphics queue, one-shot command buffers, and move-only owners of buffers, images,
// descriptor sets and pipelines. Errors throw std::runtime_error naming the call.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace example {

void check_vk(VkResult result, const char* what);

class VulkanContext {
 public:
  VulkanContext();  // throws std::runtime_error("no Vulkan device …") when there is none
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  VkDevice device() const { return device_; }
  std::string device_name() const { return device_name_; }
  bool validation() const { return validation_; }
  // The validation layer's warnings and errors so far, and the first of them.
  int messages() const { return messages_; }
  const std::string& first_message() const { return first_message_; }

  uint32_t memory_type(uint32_t allowed, VkMemoryPropertyFlags flags) const;
  // Records `commands` into a fresh command buffer, submits it and waits for it.
  void submit(const std::function<void(VkCommandBuffer)>& commands) const;

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT*, void*);
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  std::string device_name_;
  bool validation_ = false;
  int messages_ = 0;
  std::string first_message_;
};

// A host-visible, coherent buffer (the example is small: no staging).
class Buffer {
 public:
  Buffer(const VulkanContext& vk, std::size_t bytes, VkBufferUsageFlags usage, const void* data = nullptr);
  ~Buffer();
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  VkBuffer buffer() const { return buffer_; }
  const void* data() const { return mapped_; }
  std::size_t size() const { return size_; }

 private:
  const VulkanContext& vk_;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  void* mapped_ = nullptr;
  std::size_t size_;
};

// A 2D image in VK_IMAGE_LAYOUT_GENERAL from birth (every use here is in GENERAL): a view of all
// its levels (sampling) and one a level (storage writes).
class Image {
 public:
  Image(const VulkanContext& vk, VkFormat format, int width, int height, int levels, VkImageUsageFlags usage);
  ~Image();
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;
  VkImage image() const { return image_; }
  VkImageView view() const { return view_; }
  VkImageView level_view(int level) const { return level_views_.at(static_cast<std::size_t>(level)); }
  VkFormat format() const { return format_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  const VulkanContext& vk_;
  VkFormat format_;
  int width_, height_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  std::vector<VkImageView> level_views_;
};

// One resource of a descriptor set: what a binding holds, as the engine's plan has it.
struct Binding {
  uint32_t binding;
  VkDescriptorType type;
  VkImageView view = VK_NULL_HANDLE;  // images (sampled, storage, combined)
  const Buffer* buffer = nullptr;     // uniform and storage buffers
};

// A pipeline with its own set layout (set 0 only), made from the plan's bindings; `bind` makes a
// descriptor set of actual resources for one dispatch or draw.
class Pipeline {
 public:
  // Compute: one SPIR-V module, entry `entry`.
  Pipeline(const VulkanContext& vk, const std::vector<uint32_t>& spirv, const char* entry,
           const std::vector<Binding>& layout, uint32_t push_bytes);
  // Raster: vertex + fragment, one vec3 attribute at location 0, `colours` attachments and a D32F
  // depth attachment (dynamic rendering).
  Pipeline(const VulkanContext& vk, const std::vector<uint32_t>& vertex, const std::vector<uint32_t>& fragment,
           const std::vector<Binding>& layout, uint32_t push_bytes, const std::vector<VkFormat>& colours);
  ~Pipeline();
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  // A descriptor set holding `resources` (one a binding of the layout), alive as long as the pipeline.
  VkDescriptorSet bind(const std::vector<Binding>& resources);
  VkPipeline pipeline() const { return pipeline_; }
  VkPipelineLayout layout() const { return pipeline_layout_; }

 private:
  void make_layout(const std::vector<Binding>& layout, uint32_t push_bytes, VkShaderStageFlags stages);
  const VulkanContext& vk_;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkSampler sampler_ = VK_NULL_HANDLE;  // nearest, clamp: the modules only fetch texels
  std::vector<VkDescriptorPool> pools_;
  std::vector<Binding> plan_;
};

// A barrier between passes: every earlier write visible to every later read or write.
void full_barrier(VkCommandBuffer commands);

}  // namespace example
