#include "vk/vulkan_raster_program.h"

#include <utility>

#include "core/error.h"
#include "passes/scene_raster.h"  // glsl/passes: the raster passes' vertex location
#include "vk/vulkan_pipeline_parts.h"
#include "vk/vulkan_state.h"

// Vulkan's create-info structs are named by their sType and then filled field by field.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace pn::vk {

VulkanRasterProgram::VulkanRasterProgram(const VulkanDevice::State& s, std::string name,
                                         const std::vector<std::uint32_t>& vertex,
                                         const std::vector<std::uint32_t>& fragment, TexelFormat target, bool positions)
    : VulkanProgram(s, std::move(name), {{&vertex, VK_SHADER_STAGE_VERTEX_BIT}, {&fragment, VK_SHADER_STAGE_FRAGMENT_BIT}}),
      target_(target), positions_(positions) {
  if (!s.depth_clip_control)
    throw Error(name_ + ": the Vulkan device has no VK_EXT_depth_clip_control, without which GL's clip-space depth "
                        "(-1..1) cannot be kept",
                ExitCode::failed);
  render_pass_ = make_render_pass(s, target, name_);
  VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                               {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = modules_[0];
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = modules_[1];
  stages[1].pName = "main";
  const VkVertexInputBindingDescription vertex_binding{0, 3 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX};
  const VkVertexInputAttributeDescription position{PN_SCENE_POSITION_LOCATION, 0, VK_FORMAT_R32G32B32_SFLOAT, 0};
  VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertex_input.vertexBindingDescriptionCount = positions ? 1 : 0;
  vertex_input.pVertexBindingDescriptions = &vertex_binding;
  vertex_input.vertexAttributeDescriptionCount = positions ? 1 : 0;
  vertex_input.pVertexAttributeDescriptions = &position;
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportDepthClipControlCreateInfoEXT clip{
      VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_DEPTH_CLIP_CONTROL_CREATE_INFO_EXT};
  clip.negativeOneToOne = VK_TRUE;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.pNext = &clip;
  viewport.viewportCount = viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  // GL's front faces (counter-clockwise in window coordinates, y up): the targets keep GL's rows
  // (NDC y = -1 at row 0, a positive viewport), and Vulkan's facing formula negates the signed
  // area for its y-down framebuffer, so GL's counter-clockwise is Vulkan's clockwise here
  // (gl_FrontFacing in shadow_depth_back.frag; found by the shadow_map check's back-face layer).
  raster.frontFace = VK_FRONT_FACE_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth_test{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth_test.depthTestEnable = depth_test.depthWriteEnable = VK_TRUE;
  depth_test.depthCompareOp = VK_COMPARE_OP_LESS;  // GL_LESS: the nearest surface
  VkPipelineColorBlendAttachmentState blend{};
  blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                         VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo blending{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blending.attachmentCount = 1;
  blending.pAttachments = &blend;
  const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamic_states;
  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth_test;
  info.pColorBlendState = &blending;
  info.pDynamicState = &dynamic;
  info.layout = pipeline_layout_;
  info.renderPass = render_pass_;
  vk_check(vkCreateGraphicsPipelines(s.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_),
           name_ + ": a graphics pipeline");
  s.throw_if_messages(name_);
}

VulkanRasterProgram::~VulkanRasterProgram() {
  if (s_->abandoned()) return;  // a stuck job may run it (State)
  if (render_pass_ != VK_NULL_HANDLE) vkDestroyRenderPass(s_->device, render_pass_, nullptr);
}

void VulkanRasterProgram::draw(const VulkanVertices* vertices, const std::vector<VertexRun>& runs,
                               const VulkanRasterTarget& target, const std::vector<TexelRect>& rects,
                               const PassResources& resources) const {
  const VulkanDevice::State& s = *s_;
  if (positions_ != (vertices != nullptr))
    throw Error(name_ + (positions_ ? ": expected a vertex buffer" : ": a full-screen pass makes its own vertices"),
                ExitCode::failed);
  if (!resources.images.empty() || !resources.buffers.empty())
    throw Error(name_ + ": a raster pass binds textures and blocks only: expected no storage images or buffers",
                ExitCode::failed);
  if (target.colour().shape().format != target_)
    throw Error(name_ + ": a target of another format than the program's", ExitCode::failed);
  for (const VertexRun& run : runs)
    if (vertices != nullptr && (run.first < 0 || run.count < 0 || run.first + run.count > vertices->count()))
      throw Error(name_ + ": vertices " + std::to_string(run.first) + ".." + std::to_string(run.first + run.count) +
                      " of " + std::to_string(vertices->count()),
                  ExitCode::failed);
  BoundSet bound;
  bind(resources, bound);
  const int size = target.size();
  s.submit(name_ + ": draw", [&](VkCommandBuffer c) {
    VkMemoryBarrier before{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    before.srcAccessMask = VK_ACCESS_HOST_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    before.dstAccessMask = VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_UNIFORM_READ_BIT | VK_ACCESS_SHADER_READ_BIT;
    vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_VERTEX_INPUT_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT |
                             VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                         0, 1, &before, 0, nullptr, 0, nullptr);
    target.record_pass(c, [&] {
      vkCmdBindPipeline(c, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
      const VkViewport viewport{0.0f, 0.0f, float(size), float(size), 0.0f, 1.0f};
      vkCmdSetViewport(c, 0, 1, &viewport);
      bind_set(c, VK_PIPELINE_BIND_POINT_GRAPHICS, bound);
      if (vertices != nullptr) {
        const VkBuffer buffers[] = {vertices->buffer().buffer()};
        const VkDeviceSize offsets[] = {0};
        vkCmdBindVertexBuffers(c, 0, 1, buffers, offsets);
      }
      for (const VkRect2D& scissor : scissor_rects(rects, size)) {
        vkCmdSetScissor(c, 0, 1, &scissor);
        if (vertices == nullptr) vkCmdDraw(c, 3, 1, 0, 0);
        for (const VertexRun& run : vertices != nullptr ? runs : std::vector<VertexRun>{})
          if (run.count > 0) vkCmdDraw(c, static_cast<uint32_t>(run.count), 1, static_cast<uint32_t>(run.first), 0);
      }
    });
  });
}

}  // namespace pn::vk
