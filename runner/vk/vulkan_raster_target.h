// The Vulkan executor's raster targets: a colour image and its D32 depth buffer with the render
// pass and framebuffer that draw into them, triangle lists in a vertex buffer, scissored clears.
#pragma once

#include <vulkan/vulkan.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/texel_rect.h"
#include "device/query_device.h"
#include "vk/vulkan_device.h"
#include "vk/vulkan_resources.h"

namespace pn::vk {

// A D32_SFLOAT depth attachment, kept in GENERAL layout (cleared, copied and drawn into as the
// colour is).
class DepthImage {
 public:
  DepthImage(const VulkanDevice::State& s, int size);
  ~DepthImage();
  DepthImage(const DepthImage&) = delete;
  DepthImage& operator=(const DepthImage&) = delete;
  VkImage image() const { return image_; }
  VkImageView view() const { return view_; }

 private:
  const VulkanDevice::State* s_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
};

// The render pass every raster draw runs in: a colour attachment of `format` and a D32 depth
// attachment, both loaded and stored in GENERAL layout (a target keeps what it holds between
// draws). Pipelines made with it draw in any target of the same format (render pass compatibility).
VkRenderPass make_render_pass(const VulkanDevice::State& s, TexelFormat format, const std::string& name);

// A triangle list in a host-visible vertex buffer.
class VulkanVertices final : public DeviceVertices {
 public:
  VulkanVertices(const VulkanDevice::State& s, const std::vector<glm::vec3>& vertices);
  const HostBuffer& buffer() const { return buffer_; }
  const VulkanDevice::State* owner() const { return owner_; }

 private:
  HostBuffer buffer_;
  const VulkanDevice::State* owner_;
};

// A colour image and its depth buffer, with the render pass and framebuffer that draw into them.
class VulkanRasterTarget final : public DeviceRasterTarget {
 public:
  VulkanRasterTarget(const VulkanDevice::State& s, int size, TexelFormat format);
  ~VulkanRasterTarget() override;
  const DeviceTexture& texture() const override { return *colour_; }
  const VulkanDevice::State* owner() const { return s_; }
  const VulkanImage& colour() const { return *colour_; }
  std::unique_ptr<VulkanImage> take_colour() { return std::move(colour_); }
  const DepthImage& depth() const { return depth_; }

  // Records `inside` between the beginning and the end of this target's render pass, the
  // viewport on the whole target (NDC y = -1 at row 0, as GL's: texels lie where GL's lie).
  void record_pass(VkCommandBuffer c, const std::function<void()>& inside) const;

 private:
  const VulkanDevice::State* s_;
  std::unique_ptr<VulkanImage> colour_;
  DepthImage depth_;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
};

// The rectangles a scissored operation covers: each one clipped to the target, the empty ones
// dropped; the whole target for none given.
std::vector<VkRect2D> scissor_rects(const std::vector<TexelRect>& rects, int size);

// `clear` into `target` inside each rectangle (the whole target for none), depth to the far plane.
void clear_raster_target(const VulkanDevice::State& s, const VulkanRasterTarget& target, const float clear[4],
                         const std::vector<TexelRect>& rects);

}  // namespace pn::vk
