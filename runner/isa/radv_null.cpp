#include "isa/radv_null.h"

#include <vulkan/vulkan.h>

#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <functional>

#include "core/error.h"
#include "vk/vulkan_pipeline_parts.h"

// Vulkan's create-info structs are written {sType} with the rest zero, as the API means them.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace pn {

std::string radeon_icd_manifest() {
  for (const char* dir : {"/usr/share/vulkan/icd.d", "/etc/vulkan/icd.d", "/usr/local/share/vulkan/icd.d"}) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("radeon_icd", 0) == 0 && entry.path().extension() == ".json") return entry.path().string();
    }
  }
  return {};
}

void set_radv_environment(const RadvTarget& target, const std::string& manifest, const std::string& runtime_dir) {
  setenv("VK_ICD_FILENAMES", manifest.c_str(), 1);
  setenv("VK_DRIVER_FILES", manifest.c_str(), 1);
  unsetenv("VK_INSTANCE_LAYERS");
  setenv("RADV_FORCE_FAMILY", target.family.c_str(), 1);
  if (target.wave == 32)
    setenv("RADV_PERFTEST", "cswave32,pswave32", 1);
  else
    unsetenv("RADV_PERFTEST");
  // Every compile is ACO's, not a cached binary. PN_ISA_RADV_DEBUG adds RADV's own flags for a
  // reader of the compiler (docs/isa.md: "shaders" with ACO_DEBUG=liveinfo prints register demand).
  std::string debug = "nocache";
  if (const char* extra = std::getenv("PN_ISA_RADV_DEBUG"); extra && *extra) debug += std::string(",") + extra;
  setenv("RADV_DEBUG", debug.c_str(), 1);
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  setenv("XDG_RUNTIME_DIR", runtime_dir.c_str(), 1);
}

double ShaderExecutable::statistic(const std::string& wanted) const {
  for (const auto& [name, value] : statistics)
    if (name == wanted) return value;
  return -1.0;
}

namespace {

// A Vulkan handle destroyed by `destroy` when it goes.
template <typename Handle>
class Owned {
 public:
  explicit Owned(std::function<void(Handle)> destroy) : destroy_(std::move(destroy)) {}
  ~Owned() {
    if (handle != VK_NULL_HANDLE) destroy_(handle);
  }
  Owned(const Owned&) = delete;
  Owned& operator=(const Owned&) = delete;
  Handle handle = VK_NULL_HANDLE;

 private:
  std::function<void(Handle)> destroy_;
};

Stage stage_of_bits(VkShaderStageFlags stages) {
  if (stages & VK_SHADER_STAGE_VERTEX_BIT) return Stage::vertex;
  if (stages & VK_SHADER_STAGE_FRAGMENT_BIT) return Stage::fragment;
  return Stage::compute;
}

}  // namespace

struct RadvNullDevice::State {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  std::string name;
  PFN_vkGetPipelineExecutablePropertiesKHR properties = nullptr;
  PFN_vkGetPipelineExecutableStatisticsKHR statistics = nullptr;
  PFN_vkGetPipelineExecutableInternalRepresentationsKHR representations = nullptr;
  ~State() {
    if (device != VK_NULL_HANDLE) vkDestroyDevice(device, nullptr);
    if (instance != VK_NULL_HANDLE) vkDestroyInstance(instance, nullptr);
  }

  // The set layout every stage's resources need (vk/vulkan_pipeline_parts.h).
  VkDescriptorSetLayout set_layout(
      const std::vector<std::pair<const std::vector<std::uint32_t>*, VkShaderStageFlagBits>>& stages,
      const std::string& name) const {
    const SetLayoutBindings set = set_layout_bindings(stages, name);
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = static_cast<uint32_t>(set.layout.size());
    info.pBindings = set.layout.data();
    VkDescriptorSetLayout l = VK_NULL_HANDLE;
    vk_check(vkCreateDescriptorSetLayout(device, &info, nullptr, &l), name + ": a set layout");
    return l;
  }

  std::vector<ShaderExecutable> executables(VkPipeline pipeline, const std::string& name) const {
    VkPipelineInfoKHR info{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR};
    info.pipeline = pipeline;
    uint32_t count = 0;
    vk_check(properties(device, &info, &count, nullptr), name + ": its executables");
    std::vector<VkPipelineExecutablePropertiesKHR> props(count, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR});
    vk_check(properties(device, &info, &count, props.data()), name + ": its executables");
    std::vector<ShaderExecutable> out;
    for (uint32_t i = 0; i < count; ++i) {
      ShaderExecutable e;
      e.stage = stage_of_bits(props[i].stages);
      e.name = props[i].name;
      VkPipelineExecutableInfoKHR which{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR};
      which.pipeline = pipeline;
      which.executableIndex = i;
      uint32_t n = 0;
      vk_check(statistics(device, &which, &n, nullptr), name + ": its statistics");
      std::vector<VkPipelineExecutableStatisticKHR> stats(n, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR});
      vk_check(statistics(device, &which, &n, stats.data()), name + ": its statistics");
      for (const auto& s : stats) {
        double v = 0.0;
        switch (s.format) {
          case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR: v = s.value.b32; break;
          case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR: v = static_cast<double>(s.value.i64); break;
          case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR: v = static_cast<double>(s.value.u64); break;
          case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_FLOAT64_KHR: v = s.value.f64; break;
          default: break;
        }
        e.statistics.emplace_back(s.name, v);
      }
      uint32_t r = 0;
      vk_check(representations(device, &which, &r, nullptr), name + ": its representations");
      std::vector<VkPipelineExecutableInternalRepresentationKHR> reps(r, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INTERNAL_REPRESENTATION_KHR});
      vk_check(representations(device, &which, &r, reps.data()), name + ": its representations");
      std::vector<std::string> texts(r);
      for (uint32_t k = 0; k < r; ++k) {
        texts[k].assign(reps[k].dataSize, '\0');
        reps[k].pData = texts[k].data();
      }
      vk_check(representations(device, &which, &r, reps.data()), name + ": its representations");
      for (uint32_t k = 0; k < r; ++k) {
        const std::string rep_name = reps[k].name;
        if (rep_name.find("Assembly") != std::string::npos || rep_name.find("ISA") != std::string::npos ||
            rep_name.find("assembly") != std::string::npos) {
          std::string t = texts[k];
          t.resize(std::strlen(t.c_str()));
          e.isa = t;
        }
      }
      out.push_back(std::move(e));
    }
    return out;
  }
};

RadvNullDevice::RadvNullDevice() : s_(std::make_unique<State>()) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "penumbra isa";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo instance_info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  instance_info.pApplicationInfo = &app;
  vk_check(vkCreateInstance(&instance_info, nullptr, &s_->instance), "the RADV null device: vkCreateInstance");
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(s_->instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(s_->instance, &count, devices.data());
  std::string seen;
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    const std::string name = p.deviceName;
    seen += (seen.empty() ? "" : ", ") + name;
    if (name.find("RADV") != std::string::npos && s_->physical == VK_NULL_HANDLE) {
      s_->physical = d;
      s_->name = name;
    }
  }
  if (s_->physical == VK_NULL_HANDLE)
    throw Error("the RADV null device did not come up (devices: " + (seen.empty() ? std::string("none") : seen) + ")",
                ExitCode::failed);
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue.queueFamilyIndex = 0;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR executable_info{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
  executable_info.pipelineExecutableInfo = VK_TRUE;
  const char* extension = VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME;
  VkDeviceCreateInfo device_info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  device_info.pNext = &executable_info;
  device_info.queueCreateInfoCount = 1;
  device_info.pQueueCreateInfos = &queue;
  device_info.enabledExtensionCount = 1;
  device_info.ppEnabledExtensionNames = &extension;
  vk_check(vkCreateDevice(s_->physical, &device_info, nullptr, &s_->device), "vkCreateDevice on " + s_->name);
  s_->properties = reinterpret_cast<PFN_vkGetPipelineExecutablePropertiesKHR>(
      vkGetDeviceProcAddr(s_->device, "vkGetPipelineExecutablePropertiesKHR"));
  s_->statistics = reinterpret_cast<PFN_vkGetPipelineExecutableStatisticsKHR>(
      vkGetDeviceProcAddr(s_->device, "vkGetPipelineExecutableStatisticsKHR"));
  s_->representations = reinterpret_cast<PFN_vkGetPipelineExecutableInternalRepresentationsKHR>(
      vkGetDeviceProcAddr(s_->device, "vkGetPipelineExecutableInternalRepresentationsKHR"));
  if (!s_->properties || !s_->statistics || !s_->representations)
    throw Error(s_->name + ": VK_KHR_pipeline_executable_properties has no entry points", ExitCode::failed);
}

RadvNullDevice::~RadvNullDevice() = default;

std::string RadvNullDevice::device_name() const { return s_->name; }

int RadvNullDevice::min_wave() const {
  VkPhysicalDeviceSubgroupSizeControlPropertiesEXT sizes{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_SIZE_CONTROL_PROPERTIES_EXT};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  properties.pNext = &sizes;
  vkGetPhysicalDeviceProperties2(s_->physical, &properties);
  return static_cast<int>(sizes.minSubgroupSize);
}

std::vector<ShaderExecutable> RadvNullDevice::compile_compute(const std::vector<std::uint32_t>& spirv,
                                                              const std::string& name) const {
  const State& s = *s_;
  const VkDevice device = s.device;
  Owned<VkShaderModule> module([device](VkShaderModule m) { vkDestroyShaderModule(device, m, nullptr); });
  module.handle = make_shader_module(device, spirv, name);
  Owned<VkDescriptorSetLayout> set([device](VkDescriptorSetLayout l) { vkDestroyDescriptorSetLayout(device, l, nullptr); });
  set.handle = s.set_layout({{&spirv, VK_SHADER_STAGE_COMPUTE_BIT}}, name);
  Owned<VkPipelineLayout> layout([device](VkPipelineLayout l) { vkDestroyPipelineLayout(device, l, nullptr); });
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set.handle;
  vk_check(vkCreatePipelineLayout(device, &layout_info, nullptr, &layout.handle), name + ": a pipeline layout");
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.flags = VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR | VK_PIPELINE_CREATE_CAPTURE_INTERNAL_REPRESENTATIONS_BIT_KHR;
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module.handle;
  info.stage.pName = "main";
  info.layout = layout.handle;
  Owned<VkPipeline> pipeline([device](VkPipeline p) { vkDestroyPipeline(device, p, nullptr); });
  vk_check(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline.handle), name + ": the compute pipeline");
  return s.executables(pipeline.handle, name);
}

std::vector<ShaderExecutable> RadvNullDevice::compile_graphics(const std::vector<std::uint32_t>& vertex,
                                                               const std::vector<std::uint32_t>& fragment,
                                                               const std::string& name) const {
  const State& s = *s_;
  const VkDevice device = s.device;
  auto destroy_module = [device](VkShaderModule m) { vkDestroyShaderModule(device, m, nullptr); };
  Owned<VkShaderModule> vs(destroy_module), fs(destroy_module);
  vs.handle = make_shader_module(device, vertex, name + " (vertex)");
  fs.handle = make_shader_module(device, fragment, name);
  Owned<VkDescriptorSetLayout> set([device](VkDescriptorSetLayout l) { vkDestroyDescriptorSetLayout(device, l, nullptr); });
  set.handle = s.set_layout({{&vertex, VK_SHADER_STAGE_VERTEX_BIT}, {&fragment, VK_SHADER_STAGE_FRAGMENT_BIT}}, name);
  Owned<VkPipelineLayout> layout([device](VkPipelineLayout l) { vkDestroyPipelineLayout(device, l, nullptr); });
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set.handle;
  vk_check(vkCreatePipelineLayout(device, &layout_info, nullptr, &layout.handle), name + ": a pipeline layout");

  VkAttachmentDescription attachments[2] = {};
  attachments[0].format = VK_FORMAT_R32G32B32A32_SFLOAT;
  attachments[1].format = VK_FORMAT_D32_SFLOAT;
  for (auto& a : attachments) {
    a.samples = VK_SAMPLE_COUNT_1_BIT;
    a.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    a.initialLayout = a.finalLayout = VK_IMAGE_LAYOUT_GENERAL;
  }
  VkAttachmentReference colour{0, VK_IMAGE_LAYOUT_GENERAL}, depth{1, VK_IMAGE_LAYOUT_GENERAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colour;
  subpass.pDepthStencilAttachment = &depth;
  VkRenderPassCreateInfo pass_info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  pass_info.attachmentCount = 2;
  pass_info.pAttachments = attachments;
  pass_info.subpassCount = 1;
  pass_info.pSubpasses = &subpass;
  Owned<VkRenderPass> render_pass([device](VkRenderPass p) { vkDestroyRenderPass(device, p, nullptr); });
  vk_check(vkCreateRenderPass(device, &pass_info, nullptr, &render_pass.handle), name + ": a render pass");

  VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                               {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vs.handle;
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = fs.handle;
  stages[1].pName = "main";
  // The scene passes read a position (vec3) and a normal (vec3) at locations 0 and 1: a full-screen
  // triangle's vertex shader reads none, and unused attributes cost nothing.
  VkVertexInputBindingDescription binding{0, 6 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX};
  VkVertexInputAttributeDescription attributes[2] = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                                                     {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 3 * sizeof(float)}};
  VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertex_input.vertexBindingDescriptionCount = 1;
  vertex_input.pVertexBindingDescriptions = &binding;
  vertex_input.vertexAttributeDescriptionCount = 2;
  vertex_input.pVertexAttributeDescriptions = attributes;
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth_state{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth_state.depthTestEnable = VK_TRUE;
  depth_state.depthWriteEnable = VK_TRUE;
  depth_state.depthCompareOp = VK_COMPARE_OP_LESS;
  VkPipelineColorBlendAttachmentState blend_attachment{};
  blend_attachment.colorWriteMask = 0xF;
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = 1;
  blend.pAttachments = &blend_attachment;
  const VkDynamicState dynamic_states[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamic_states;
  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.flags = VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR | VK_PIPELINE_CREATE_CAPTURE_INTERNAL_REPRESENTATIONS_BIT_KHR;
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth_state;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout.handle;
  info.renderPass = render_pass.handle;
  Owned<VkPipeline> pipeline([device](VkPipeline p) { vkDestroyPipeline(device, p, nullptr); });
  vk_check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline.handle), name + ": the graphics pipeline");
  return s.executables(pipeline.handle, name);
}

}  // namespace pn
