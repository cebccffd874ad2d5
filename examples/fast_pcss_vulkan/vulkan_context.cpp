#include "vulkan_context.h"

#include <cstring>
#include <stdexcept>

// Vulkan's create-info structs are named by their sType and then filled field by field.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace example {

void check_vk(VkResult result, const char* what) {
  if (result != VK_SUCCESS) throw std::runtime_error(std::string("vulkan: ") + what + " failed (VkResult " +
                                                     std::to_string(static_cast<int>(result)) + ")");
}

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool has_validation_layer() {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const VkLayerProperties& l : layers)
    if (std::strcmp(l.layerName, kValidationLayer) == 0) return true;
  return false;
}

VkShaderModule make_module(VkDevice device, const std::vector<uint32_t>& spirv) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = spirv.size() * sizeof(uint32_t);
  info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  check_vk(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule");
  return module;
}

}  // namespace

VKAPI_ATTR VkBool32 VKAPI_CALL VulkanContext::on_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                         VkDebugUtilsMessageTypeFlagsEXT,
                                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void* self) {
  auto* context = static_cast<VulkanContext*>(self);
  if (context->messages_++ == 0) context->first_message_ = data->pMessage;
  return VK_FALSE;
}

VulkanContext::VulkanContext() {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "fast_pcss_vulkan_example";
  app.apiVersion = VK_API_VERSION_1_3;  // dynamic rendering
  validation_ = has_validation_layer();
  VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  // Not its performance hints: every image here stays in VK_IMAGE_LAYOUT_GENERAL, on purpose (plain code).
  messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
  messenger.pfnUserCallback = on_message;
  messenger.pUserData = this;
  const char* layers[] = {kValidationLayer};
  const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  if (validation_) {
    info.enabledLayerCount = 1, info.ppEnabledLayerNames = layers;
    info.enabledExtensionCount = 1, info.ppEnabledExtensionNames = extensions;
    info.pNext = &messenger;
  }
  if (vkCreateInstance(&info, nullptr, &instance_) != VK_SUCCESS)
    throw std::runtime_error("no Vulkan device: vkCreateInstance failed (is a Vulkan driver, e.g. lavapipe, installed?)");
  if (validation_) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    check_vk(create(instance_, &messenger, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
  }

  // The first device (lavapipe on the CI machine) with a queue for graphics and compute, Vulkan 1.3.
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance_, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance_, &count, devices.data());
  uint32_t family = 0;
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(d, &properties);
    if (properties.apiVersion < VK_API_VERSION_1_3) continue;
    uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(d, &families, nullptr);
    std::vector<VkQueueFamilyProperties> list(families);
    vkGetPhysicalDeviceQueueFamilyProperties(d, &families, list.data());
    for (uint32_t f = 0; f < families && physical_ == VK_NULL_HANDLE; ++f)
      if ((list[f].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) ==
          (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT))
        physical_ = d, family = f, device_name_ = properties.deviceName;
    if (physical_ != VK_NULL_HANDLE) break;
  }
  if (physical_ == VK_NULL_HANDLE) throw std::runtime_error("no Vulkan device with Vulkan 1.3 and a graphics-and-compute queue");

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue.queueFamilyIndex = family, queue.queueCount = 1, queue.pQueuePriorities = &priority;
  VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  features13.dynamicRendering = VK_TRUE;
  VkDeviceCreateInfo device_info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  device_info.pNext = &features13;
  device_info.queueCreateInfoCount = 1, device_info.pQueueCreateInfos = &queue;
  check_vk(vkCreateDevice(physical_, &device_info, nullptr, &device_), "vkCreateDevice");
  vkGetDeviceQueue(device_, family, 0, &queue_);
  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.queueFamilyIndex = family;
  check_vk(vkCreateCommandPool(device_, &pool, nullptr, &pool_), "vkCreateCommandPool");
}

VulkanContext::~VulkanContext() {
  if (device_ != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device_);
    vkDestroyCommandPool(device_, pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (messenger_ != VK_NULL_HANDLE) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(instance_, messenger_, nullptr);
  }
  if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
}

uint32_t VulkanContext::memory_type(uint32_t allowed, VkMemoryPropertyFlags flags) const {
  VkPhysicalDeviceMemoryProperties memory;
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory);
  for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
    if ((allowed & (1u << i)) != 0 && (memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
  throw std::runtime_error("vulkan: no memory type with the flags needed");
}

void VulkanContext::submit(const std::function<void(VkCommandBuffer)>& commands) const {
  VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocate.commandPool = pool_, allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY, allocate.commandBufferCount = 1;
  VkCommandBuffer c = VK_NULL_HANDLE;
  check_vk(vkAllocateCommandBuffers(device_, &allocate, &c), "vkAllocateCommandBuffers");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check_vk(vkBeginCommandBuffer(c, &begin), "vkBeginCommandBuffer");
  commands(c);
  check_vk(vkEndCommandBuffer(c), "vkEndCommandBuffer");
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1, submit.pCommandBuffers = &c;
  check_vk(vkQueueSubmit(queue_, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
  check_vk(vkQueueWaitIdle(queue_), "vkQueueWaitIdle");
  vkFreeCommandBuffers(device_, pool_, 1, &c);
}

Buffer::Buffer(const VulkanContext& vk, std::size_t bytes, VkBufferUsageFlags usage, const void* data)
    : vk_(vk), size_(bytes) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = bytes, info.usage = usage, info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  check_vk(vkCreateBuffer(vk.device(), &info, nullptr, &buffer_), "vkCreateBuffer");
  VkMemoryRequirements needs;
  vkGetBufferMemoryRequirements(vk.device(), buffer_, &needs);
  VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocate.allocationSize = needs.size;
  allocate.memoryTypeIndex =
      vk.memory_type(needs.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  check_vk(vkAllocateMemory(vk.device(), &allocate, nullptr, &memory_), "vkAllocateMemory");
  check_vk(vkBindBufferMemory(vk.device(), buffer_, memory_, 0), "vkBindBufferMemory");
  check_vk(vkMapMemory(vk.device(), memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
  if (data != nullptr) std::memcpy(mapped_, data, bytes);
}

Buffer::~Buffer() {
  vkDestroyBuffer(vk_.device(), buffer_, nullptr);
  vkFreeMemory(vk_.device(), memory_, nullptr);
}

Image::Image(const VulkanContext& vk, VkFormat format, int width, int height, int levels, VkImageUsageFlags usage)
    : vk_(vk), format_(format), width_(width), height_(height) {
  const bool depth = format == VK_FORMAT_D32_SFLOAT;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D, info.format = format;
  info.extent = {static_cast<uint32_t>(width), static_cast<uint32_t>(height), 1};
  info.mipLevels = static_cast<uint32_t>(levels), info.arrayLayers = 1, info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL, info.usage = usage, info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  check_vk(vkCreateImage(vk.device(), &info, nullptr, &image_), "vkCreateImage");
  VkMemoryRequirements needs;
  vkGetImageMemoryRequirements(vk.device(), image_, &needs);
  VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocate.allocationSize = needs.size;
  allocate.memoryTypeIndex = vk.memory_type(needs.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  check_vk(vkAllocateMemory(vk.device(), &allocate, nullptr, &memory_), "vkAllocateMemory");
  check_vk(vkBindImageMemory(vk.device(), image_, memory_, 0), "vkBindImageMemory");
  const VkImageAspectFlags aspect = depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
  const auto make_view = [&](int first, int count) {
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image_, view.viewType = VK_IMAGE_VIEW_TYPE_2D, view.format = format;
    view.subresourceRange = {aspect, static_cast<uint32_t>(first), static_cast<uint32_t>(count), 0, 1};
    VkImageView made = VK_NULL_HANDLE;
    check_vk(vkCreateImageView(vk.device(), &view, nullptr, &made), "vkCreateImageView");
    return made;
  };
  view_ = make_view(0, levels);
  for (int level = 0; level < levels; ++level) level_views_.push_back(make_view(level, 1));
  vk.submit([&](VkCommandBuffer c) {
    VkImageMemoryBarrier to_general{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    to_general.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
    to_general.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED, to_general.newLayout = VK_IMAGE_LAYOUT_GENERAL;
    to_general.srcQueueFamilyIndex = to_general.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    to_general.image = image_;
    to_general.subresourceRange = {aspect, 0, static_cast<uint32_t>(levels), 0, 1};
    vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &to_general);
  });
}

Image::~Image() {
  for (VkImageView v : level_views_) vkDestroyImageView(vk_.device(), v, nullptr);
  vkDestroyImageView(vk_.device(), view_, nullptr);
  vkDestroyImage(vk_.device(), image_, nullptr);
  vkFreeMemory(vk_.device(), memory_, nullptr);
}

void Pipeline::make_layout(const std::vector<Binding>& layout, uint32_t push_bytes, VkShaderStageFlags stages) {
  plan_ = layout;
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (const Binding& b : layout) bindings.push_back({b.binding, b.type, 1, stages, nullptr});
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = static_cast<uint32_t>(bindings.size()), info.pBindings = bindings.data();
  check_vk(vkCreateDescriptorSetLayout(vk_.device(), &info, nullptr, &set_layout_), "vkCreateDescriptorSetLayout");
  const VkPushConstantRange push{stages, 0, push_bytes};
  VkPipelineLayoutCreateInfo pipeline_layout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pipeline_layout.setLayoutCount = 1, pipeline_layout.pSetLayouts = &set_layout_;
  if (push_bytes > 0) pipeline_layout.pushConstantRangeCount = 1, pipeline_layout.pPushConstantRanges = &push;
  check_vk(vkCreatePipelineLayout(vk_.device(), &pipeline_layout, nullptr, &pipeline_layout_), "vkCreatePipelineLayout");
  VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sampler.magFilter = sampler.minFilter = VK_FILTER_NEAREST;
  sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  sampler.addressModeU = sampler.addressModeV = sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  sampler.maxLod = VK_LOD_CLAMP_NONE;
  check_vk(vkCreateSampler(vk_.device(), &sampler, nullptr, &sampler_), "vkCreateSampler");
}

Pipeline::Pipeline(const VulkanContext& vk, const std::vector<uint32_t>& spirv, const char* entry,
                   const std::vector<Binding>& layout, uint32_t push_bytes)
    : vk_(vk) {
  make_layout(layout, push_bytes, VK_SHADER_STAGE_COMPUTE_BIT);
  const VkShaderModule module = make_module(vk.device(), spirv);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT, info.stage.module = module, info.stage.pName = entry;
  info.layout = pipeline_layout_;
  const VkResult made = vkCreateComputePipelines(vk.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_);
  vkDestroyShaderModule(vk.device(), module, nullptr);
  check_vk(made, "vkCreateComputePipelines");
}

Pipeline::Pipeline(const VulkanContext& vk, const std::vector<uint32_t>& vertex, const std::vector<uint32_t>& fragment,
                   const std::vector<Binding>& layout, uint32_t push_bytes, const std::vector<VkFormat>& colours)
    : vk_(vk) {
  make_layout(layout, push_bytes, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
  const VkShaderModule modules[] = {make_module(vk.device(), vertex), make_module(vk.device(), fragment)};
  VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                               {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT, stages[0].module = modules[0], stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT, stages[1].module = modules[1], stages[1].pName = "main";
  const VkVertexInputBindingDescription vertex_binding{0, 3 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX};
  const VkVertexInputAttributeDescription position{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0};
  VkPipelineVertexInputStateCreateInfo input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  input.vertexBindingDescriptionCount = 1, input.pVertexBindingDescriptions = &vertex_binding;
  input.vertexAttributeDescriptionCount = 1, input.pVertexAttributeDescriptions = &position;
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1, viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL, raster.cullMode = VK_CULL_MODE_NONE, raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE, depth.depthWriteEnable = VK_TRUE, depth.depthCompareOp = VK_COMPARE_OP_LESS;
  std::vector<VkPipelineColorBlendAttachmentState> blend(colours.size());
  for (auto& b : blend) b.colorWriteMask = 0xF;
  VkPipelineColorBlendStateCreateInfo blending{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blending.attachmentCount = static_cast<uint32_t>(blend.size()), blending.pAttachments = blend.data();
  const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2, dynamic.pDynamicStates = dynamic_states;
  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = static_cast<uint32_t>(colours.size());
  rendering.pColorAttachmentFormats = colours.data();
  rendering.depthAttachmentFormat = VK_FORMAT_D32_SFLOAT;
  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.pNext = &rendering;
  info.stageCount = 2, info.pStages = stages;
  info.pVertexInputState = &input, info.pInputAssemblyState = &assembly, info.pViewportState = &viewport;
  info.pRasterizationState = &raster, info.pMultisampleState = &multisample, info.pDepthStencilState = &depth;
  info.pColorBlendState = &blending, info.pDynamicState = &dynamic, info.layout = pipeline_layout_;
  const VkResult made = vkCreateGraphicsPipelines(vk.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_);
  for (VkShaderModule m : modules) vkDestroyShaderModule(vk.device(), m, nullptr);
  check_vk(made, "vkCreateGraphicsPipelines");
}

Pipeline::~Pipeline() {
  for (VkDescriptorPool p : pools_) vkDestroyDescriptorPool(vk_.device(), p, nullptr);
  vkDestroySampler(vk_.device(), sampler_, nullptr);
  vkDestroyPipeline(vk_.device(), pipeline_, nullptr);
  vkDestroyPipelineLayout(vk_.device(), pipeline_layout_, nullptr);
  vkDestroyDescriptorSetLayout(vk_.device(), set_layout_, nullptr);
}

VkDescriptorSet Pipeline::bind(const std::vector<Binding>& resources) {
  if (resources.size() != plan_.size()) throw std::logic_error("a descriptor set must fill every binding of its layout");
  std::vector<VkDescriptorPoolSize> sizes;
  for (const Binding& b : plan_) sizes.push_back({b.type, 1});
  VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool.maxSets = 1, pool.poolSizeCount = static_cast<uint32_t>(sizes.size()), pool.pPoolSizes = sizes.data();
  pools_.push_back(VK_NULL_HANDLE);
  check_vk(vkCreateDescriptorPool(vk_.device(), &pool, nullptr, &pools_.back()), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocate.descriptorPool = pools_.back(), allocate.descriptorSetCount = 1, allocate.pSetLayouts = &set_layout_;
  VkDescriptorSet set = VK_NULL_HANDLE;
  check_vk(vkAllocateDescriptorSets(vk_.device(), &allocate, &set), "vkAllocateDescriptorSets");
  std::vector<VkDescriptorImageInfo> images(resources.size());
  std::vector<VkDescriptorBufferInfo> buffers(resources.size());
  std::vector<VkWriteDescriptorSet> writes;
  for (std::size_t i = 0; i < resources.size(); ++i) {
    const Binding& r = resources[i];
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set, write.dstBinding = r.binding, write.descriptorCount = 1, write.descriptorType = r.type;
    if (r.buffer != nullptr) {
      buffers[i] = {r.buffer->buffer(), 0, VK_WHOLE_SIZE};
      write.pBufferInfo = &buffers[i];
    } else {
      images[i] = {sampler_, r.view, VK_IMAGE_LAYOUT_GENERAL};
      write.pImageInfo = &images[i];
    }
    writes.push_back(write);
  }
  vkUpdateDescriptorSets(vk_.device(), static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
  return set;
}

void full_barrier(VkCommandBuffer commands) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &barrier,
                       0, nullptr, 0, nullptr);
}

}  // namespace example
