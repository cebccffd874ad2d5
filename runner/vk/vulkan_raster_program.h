// The Vulkan executor's raster programs: a vertex + fragment pipeline drawing triangle lists, or a
// full-screen triangle, into a raster target in GL's conventions, scissored to rectangles.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "device/query_device.h"
#include "vk/vulkan_device.h"
#include "vk/vulkan_program.h"
#include "vk/vulkan_raster_target.h"

namespace pn::vk {

// A vertex + fragment program drawing triangle lists into a target with a depth buffer, in GL's
// conventions: clip-space depth -1..1 (VK_EXT_depth_clip_control) and NDC y = -1 at row 0, so its
// texels are where GL's raster pass puts them.
class VulkanRasterProgram final : public VulkanProgram {
 public:
  // `positions`: the vertex stage reads a world position a vertex (a triangle list); else it makes
  // its own (full_screen.vert: three vertices, no vertex input).
  VulkanRasterProgram(const VulkanDevice::State& s, std::string name, const std::vector<std::uint32_t>& vertex,
                      const std::vector<std::uint32_t>& fragment, TexelFormat target, bool positions);
  ~VulkanRasterProgram() override;
  TexelFormat target_format() const { return target_; }

  // Draws `runs` of `vertices` (a program with positions) or its own full-screen triangle (one
  // without: `vertices` null) into `target` over what it holds, scissored to each rectangle.
  void draw(const VulkanVertices* vertices, const std::vector<VertexRun>& runs, const VulkanRasterTarget& target,
            const std::vector<TexelRect>& rects, const PassResources& resources) const;

 private:
  TexelFormat target_;
  bool positions_;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
};

}  // namespace pn::vk
