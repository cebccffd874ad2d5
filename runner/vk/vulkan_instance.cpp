// create_vulkan_device (vk/vulkan_device.h): the instance (with the validation layer and its
// messenger where asked for and installed), the first device with a compute queue, GPUs before
// CPUs, with VK_EXT_depth_clip_control where it has it, its queue, command pool and sampler.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "vk/vulkan_device.h"
#include "vk/vulkan_pipeline_parts.h"
#include "vk/vulkan_state.h"

// Vulkan's create-info structs are named by their sType and then filled field by field.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace pn {

namespace {

bool has_layer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool has_instance_extension(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(),
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

bool has_device_extension(VkPhysicalDevice device, const char* name) {
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(),
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

int type_rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
  }
}

VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                     VkDebugUtilsMessageTypeFlagsEXT,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data, void* state) {
  static_cast<const VulkanDevice::State*>(state)->messages.push_back(data->pMessage ? data->pMessage : "?");
  return VK_FALSE;
}

}  // namespace

std::unique_ptr<VulkanDevice> create_vulkan_device(const VulkanSettings& settings) {
  auto s = std::make_unique<VulkanDevice::State>();
  s->settings = settings;
  const auto fail = [](const std::string& why) { return Error("no Vulkan device: " + why, ExitCode::no_context); };

  const bool debug_utils = has_instance_extension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (!settings.validation)
    s->validation_why = "not asked for";
  else if (!has_layer(vk::kValidationLayer))
    s->validation_why = std::string(vk::kValidationLayer) + " is not installed (Debian: vulkan-validationlayers)";
  else if (!debug_utils)
    s->validation_why = "no VK_EXT_debug_utils";
  else
    s->validation_on = true;

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "penumbra";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo instance_info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  instance_info.pApplicationInfo = &app;
  const char* layers[] = {vk::kValidationLayer};
  const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
  VkDebugUtilsMessengerCreateInfoEXT messenger_info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger_info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  // Not the performance hints: a result read back from GENERAL layout is what a check does once.
  messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
  messenger_info.pfnUserCallback = on_validation_message;
  messenger_info.pUserData = s.get();
  if (s->validation_on) {
    instance_info.enabledLayerCount = 1;
    instance_info.ppEnabledLayerNames = layers;
    instance_info.enabledExtensionCount = 1;
    instance_info.ppEnabledExtensionNames = extensions;
    instance_info.pNext = &messenger_info;  // messages of instance creation too
  }
  const VkResult made = vkCreateInstance(&instance_info, nullptr, &s->instance);
  if (made != VK_SUCCESS)
    throw fail("vkCreateInstance failed (VkResult " + std::to_string(static_cast<int>(made)) +
               "): no Vulkan driver installed? (Debian: mesa-vulkan-drivers)");
  if (s->validation_on) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(s->instance, "vkCreateDebugUtilsMessengerEXT"));
    if (create == nullptr || create(s->instance, &messenger_info, nullptr, &s->messenger) != VK_SUCCESS)
      throw fail("the validation layer's messenger could not be made");
  }

  uint32_t count = 0;
  vkEnumeratePhysicalDevices(s->instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(s->instance, &count, devices.data());
  int best_rank = 99;
  std::string seen;
  for (VkPhysicalDevice device : devices) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(device, &properties);
    seen += std::string(seen.empty() ? "" : ", ") + properties.deviceName;
    uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &families, nullptr);
    std::vector<VkQueueFamilyProperties> family(families);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &families, family.data());
    for (uint32_t f = 0; f < families; ++f)
      if ((family[f].queueFlags & VK_QUEUE_COMPUTE_BIT) && type_rank(properties.deviceType) < best_rank &&
          properties.apiVersion >= VK_API_VERSION_1_1) {
        best_rank = type_rank(properties.deviceType);
        s->physical = device, s->properties = properties, s->queue_family = f;
        break;
      }
  }
  if (s->physical == VK_NULL_HANDLE)
    throw fail(devices.empty() ? "the loader found no device (Debian: mesa-vulkan-drivers for lavapipe)"
                               : "no Vulkan 1.1 device with a compute queue among " + seen);
  vkGetPhysicalDeviceMemoryProperties(s->physical, &s->memory);
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 properties2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  if (s->properties.apiVersion >= VK_API_VERSION_1_2) properties2.pNext = &driver;
  vkGetPhysicalDeviceProperties2(s->physical, &properties2);
  if (properties2.pNext != nullptr) s->driver_name = driver.driverName, s->driver_info = driver.driverInfo;

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = s->queue_family;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  VkDeviceCreateInfo device_info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  device_info.queueCreateInfoCount = 1;
  device_info.pQueueCreateInfos = &queue_info;
  // Raster passes keep GL's clip-space depth (-1..1) where the device can (every raster check needs it).
  VkPhysicalDeviceDepthClipControlFeaturesEXT clip_control{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DEPTH_CLIP_CONTROL_FEATURES_EXT};
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  features.pNext = &clip_control;
  const char* clip_extension = VK_EXT_DEPTH_CLIP_CONTROL_EXTENSION_NAME;
  if (has_device_extension(s->physical, clip_extension)) {
    vkGetPhysicalDeviceFeatures2(s->physical, &features);
    s->depth_clip_control = clip_control.depthClipControl == VK_TRUE;
  }
  if (s->depth_clip_control) {
    clip_control.depthClipControl = VK_TRUE;
    features.features = {};
    device_info.pNext = &features;
    device_info.enabledExtensionCount = 1;
    device_info.ppEnabledExtensionNames = &clip_extension;
  }
  if (vkCreateDevice(s->physical, &device_info, nullptr, &s->device) != VK_SUCCESS)
    throw fail(std::string("vkCreateDevice failed on ") + s->properties.deviceName);
  vkGetDeviceQueue(s->device, s->queue_family, 0, &s->queue);
  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.queueFamilyIndex = s->queue_family;
  vk_check(vkCreateCommandPool(s->device, &pool_info, nullptr, &s->pool), "creating a command pool");
  s->waiter = std::make_unique<vk::FenceWaiter>(s->device);
  // The GL textures' sampling (gl/texture.h): nearest, clamped to the edge, one level.
  VkSamplerCreateInfo sampler_info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sampler_info.magFilter = sampler_info.minFilter = VK_FILTER_NEAREST;
  sampler_info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  sampler_info.addressModeU = sampler_info.addressModeV = sampler_info.addressModeW =
      VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  vk_check(vkCreateSampler(s->device, &sampler_info, nullptr, &s->sampler), "creating a sampler");
  s->throw_if_messages("vulkan: making the device");
  return std::unique_ptr<VulkanDevice>(new VulkanDevice(std::move(s)));
}

}  // namespace pn
