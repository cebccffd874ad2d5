#include "vk/vulkan_raster_target.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "vk/vulkan_pipeline_parts.h"
#include "vk/vulkan_state.h"

// Vulkan's create-info structs are named by their sType and then filled field by field.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace pn::vk {

DepthImage::DepthImage(const VulkanDevice::State& s, int size) : s_(&s) {
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = VK_FORMAT_D32_SFLOAT;
  info.extent = {static_cast<uint32_t>(size), static_cast<uint32_t>(size), 1};
  info.mipLevels = info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
               VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  vk_check(vkCreateImage(s.device, &info, nullptr, &image_), "creating a depth buffer");
  memory_ = bind_image_memory(s, image_, "a depth buffer");
  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = image_;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = VK_FORMAT_D32_SFLOAT;
  view.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
  vk_check(vkCreateImageView(s.device, &view, nullptr, &view_), "a depth buffer's view");
  s.submit("a depth buffer's layout", [&](VkCommandBuffer c) {
    VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    barrier.newLayout = kImageLayout;
    barrier.dstAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image_;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &barrier);
  });
}

DepthImage::~DepthImage() {
  if (s_->abandoned()) return;  // a stuck job may write it (State)
  if (view_ != VK_NULL_HANDLE) vkDestroyImageView(s_->device, view_, nullptr);
  if (image_ != VK_NULL_HANDLE) vkDestroyImage(s_->device, image_, nullptr);
  if (memory_ != VK_NULL_HANDLE) vkFreeMemory(s_->device, memory_, nullptr);
}

VkRenderPass make_render_pass(const VulkanDevice::State& s, TexelFormat format, const std::string& name) {
  VkAttachmentDescription attachments[2] = {};
  attachments[0].format = vk_format(format);
  attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
  attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[0].initialLayout = kImageLayout;
  attachments[0].finalLayout = kImageLayout;
  attachments[1] = attachments[0];
  attachments[1].format = VK_FORMAT_D32_SFLOAT;
  const VkAttachmentReference colour{0, kImageLayout};
  const VkAttachmentReference depth{1, kImageLayout};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colour;
  subpass.pDepthStencilAttachment = &depth;
  VkSubpassDependency dependencies[2] = {};
  dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[0].dstSubpass = 0;
  dependencies[0].srcStageMask = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT |
                                 VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                 VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  dependencies[0].srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT |
                                  VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  dependencies[0].dstStageMask = VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
                                 VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                 VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  dependencies[0].dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                                  VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                  VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
  dependencies[1].srcSubpass = 0;
  dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  dependencies[1].dstStageMask = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
                                 VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependencies[1].dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  VkRenderPassCreateInfo pass_info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  pass_info.attachmentCount = 2;
  pass_info.pAttachments = attachments;
  pass_info.subpassCount = 1;
  pass_info.pSubpasses = &subpass;
  pass_info.dependencyCount = 2;
  pass_info.pDependencies = dependencies;
  VkRenderPass out = VK_NULL_HANDLE;
  vk_check(vkCreateRenderPass(s.device, &pass_info, nullptr, &out), name + ": a render pass");
  return out;
}

VulkanVertices::VulkanVertices(const VulkanDevice::State& s, const std::vector<glm::vec3>& vertices)
    : DeviceVertices(static_cast<int>(vertices.size())),
      buffer_(s, std::max<std::size_t>(vertices.size(), 1) * sizeof(glm::vec3), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT),
      owner_(&s) {
  if (!vertices.empty()) std::memcpy(buffer_.data(), vertices.data(), vertices.size() * sizeof(glm::vec3));
}

VulkanRasterTarget::VulkanRasterTarget(const VulkanDevice::State& s, int size, TexelFormat format)
    : s_(&s), colour_(std::make_unique<VulkanImage>(s, TextureShape{format, size, size})), depth_(s, size),
      render_pass_(make_render_pass(s, format, "a raster target")) {
  colour_->fill(nullptr, 0);  // into GENERAL layout
  const VkImageView views[2] = {colour_->level_view(0), depth_.view()};
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = render_pass_;
  info.attachmentCount = 2;
  info.pAttachments = views;
  info.width = info.height = static_cast<uint32_t>(size);
  info.layers = 1;
  vk_check(vkCreateFramebuffer(s.device, &info, nullptr, &framebuffer_), "a raster target's framebuffer");
}

VulkanRasterTarget::~VulkanRasterTarget() {
  if (s_->abandoned()) return;  // a stuck job may draw into it (State)
  if (framebuffer_ != VK_NULL_HANDLE) vkDestroyFramebuffer(s_->device, framebuffer_, nullptr);
  if (render_pass_ != VK_NULL_HANDLE) vkDestroyRenderPass(s_->device, render_pass_, nullptr);
}

void VulkanRasterTarget::record_pass(VkCommandBuffer c, const std::function<void()>& inside) const {
  const uint32_t side = static_cast<uint32_t>(size());
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = render_pass_;
  begin.framebuffer = framebuffer_;
  begin.renderArea = {{0, 0}, {side, side}};
  vkCmdBeginRenderPass(c, &begin, VK_SUBPASS_CONTENTS_INLINE);
  inside();
  vkCmdEndRenderPass(c);
}

std::vector<VkRect2D> scissor_rects(const std::vector<TexelRect>& rects, int size) {
  std::vector<VkRect2D> out;
  const TexelRect whole = TexelRect::square(size);
  for (const TexelRect& given : rects.empty() ? std::vector<TexelRect>{whole} : rects) {
    const TexelRect r = intersection(given, whole);
    if (r.empty()) continue;
    out.push_back({{r.x0, r.y0}, {static_cast<uint32_t>(r.x1 - r.x0), static_cast<uint32_t>(r.y1 - r.y0)}});
  }
  return out;
}

void clear_raster_target(const VulkanDevice::State& s, const VulkanRasterTarget& target, const float clear[4],
                         const std::vector<TexelRect>& rects) {
  VkClearAttachment clears[2] = {};
  clears[0].aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
  clears[0].colorAttachment = 0;
  for (int c = 0; c < 4; ++c) clears[0].clearValue.color.float32[c] = clear[c];
  clears[1].aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
  clears[1].clearValue.depthStencil = {1.0f, 0};
  std::vector<VkClearRect> areas;
  for (const VkRect2D& r : scissor_rects(rects, target.size())) areas.push_back({r, 0, 1});
  if (areas.empty()) return;
  s.submit("clearing a raster target", [&](VkCommandBuffer c) {
    target.record_pass(c, [&] { vkCmdClearAttachments(c, 2, clears, static_cast<uint32_t>(areas.size()), areas.data()); });
  });
}

}  // namespace pn::vk
