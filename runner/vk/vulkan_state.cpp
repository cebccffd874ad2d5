#include "vk/vulkan_state.h"

#include <chrono>

#include "core/error.h"
#include "core/format.h"
#include "vk/vulkan_pipeline_parts.h"

// Vulkan's create-info structs are named by their sType and then filled field by field.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace pn {

VulkanDevice::State::~State() {
  if (abandoned() && !stuck_job_ended(0.0)) {
    abandoned_jobs() = true;
    static_cast<void>(waiter.release());  // blocked in the driver: it leaks with the device it waits on
    return;
  }
  waiter.reset();
  if (device != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device);
    if (sampler != VK_NULL_HANDLE) vkDestroySampler(device, sampler, nullptr);
    if (pool != VK_NULL_HANDLE) vkDestroyCommandPool(device, pool, nullptr);
    vkDestroyDevice(device, nullptr);
  }
  if (messenger != VK_NULL_HANDLE) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy != nullptr) destroy(instance, messenger, nullptr);
  }
  if (instance != VK_NULL_HANDLE) vkDestroyInstance(instance, nullptr);
}

void VulkanDevice::State::throw_if_messages(const std::string& what) const {
  if (messages.empty()) return;
  std::string first = messages.front();
  const size_t more = messages.size() - 1;
  messages.clear();
  throw Error(what + ": Vulkan validation: " + first + (more ? " (and " + std::to_string(more) + " more)" : ""),
              ExitCode::failed);
}

uint32_t VulkanDevice::State::memory_type(uint32_t bits, VkMemoryPropertyFlags flags) const {
  for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
    if ((bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
  throw Error("vulkan: no memory type with the properties a buffer or image needs", ExitCode::failed);
}

bool& VulkanDevice::State::abandoned_jobs() {
  static bool any = false;
  return any;
}

bool VulkanDevice::State::stuck_job_ended(double seconds) const {
  VkResult result = VK_SUCCESS;
  if (!waiter->wait(seconds, result)) return false;
  vkDestroyFence(device, stuck_fence, nullptr);
  vkFreeCommandBuffers(device, pool, 1, &stuck_commands);
  stuck_fence = VK_NULL_HANDLE, stuck_commands = VK_NULL_HANDLE, stuck_what.clear();
  return true;
}

void VulkanDevice::State::ensure_usable(const std::string& what) const {
  if (!abandoned()) return;
  if (!given_up && stuck_job_ended(timeout_s())) return;
  given_up = true;
  throw Error(what + ": not run: the Vulkan device still runs the job that " + stuck_what +
                  " (a Vulkan job cannot be cancelled)",
              ExitCode::failed);
}

void VulkanDevice::State::submit(const std::string& what, const std::function<void(VkCommandBuffer)>& record) const {
  ensure_usable(what);
  const double timeout_s = this->timeout_s();
  VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocate.commandPool = pool;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  vk_check(vkAllocateCommandBuffers(device, &allocate, &commands), what + ": allocating commands");
  struct Free {
    const State* s;
    VkCommandBuffer c;
    ~Free() {
      if (c != VK_NULL_HANDLE) vkFreeCommandBuffers(s->device, s->pool, 1, &c);
    }
  } free_commands{this, commands};
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vk_check(vkBeginCommandBuffer(commands, &begin), what + ": recording");
  record(commands);
  vk_check(vkEndCommandBuffer(commands), what + ": recording");
  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  vk_check(vkCreateFence(device, &fence_info, nullptr, &fence), what + ": a fence");
  struct DestroyFence {
    VkDevice d;
    VkFence f;
    ~DestroyFence() {
      if (f != VK_NULL_HANDLE) vkDestroyFence(d, f, nullptr);
    }
  } destroy_fence{device, fence};
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands;
  vk_check(vkQueueSubmit(queue, 1, &submit, fence), what + ": submitting");
  waiter->start(fence);
  VkResult waited = VK_SUCCESS;
  const auto start = std::chrono::steady_clock::now();
  const bool ended = waiter->wait(timeout_s, waited);
  device_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!ended) {
    // Still running: its commands and fence are kept, and so is everything it reads (State).
    stuck_fence = fence, stuck_commands = commands;
    destroy_fence.f = VK_NULL_HANDLE, free_commands.c = VK_NULL_HANDLE;
    stuck_what = what + " did not finish within " + format_number("%g", timeout_s) + " s";
    throw Error(stuck_what, ExitCode::failed);
  }
  vk_check(waited, what + ": waiting");
  throw_if_messages(what);
  if (bounds.enabled && device_seconds > kBudgetFactor * timeout_s)
    throw Error(what + ": the check's device work did not finish within " +
                    format_number("%g", kBudgetFactor * timeout_s) + " s (" + format_number("%g", kBudgetFactor) +
                    " x --gpu-timeout, over all its dispatches)",
                ExitCode::failed);
}

bool vulkan_job_abandoned() { return VulkanDevice::State::abandoned_jobs(); }

}  // namespace pn
