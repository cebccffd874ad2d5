// What every object of the Vulkan executor shares (VulkanDevice::State): the instance, device,
// queue, command pool and sampler, the validation layer's messages, and one-shot submissions under
// the dispatch bounds' deadline — with what happens to the device when a job outlives it.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "device/pass_origin.h"
#include "shader/glslang_compiler.h"
#include "shader/loop_guard.h"
#include "vk/fence_waiter.h"
#include "vk/vulkan_device.h"

namespace pn {

namespace vk {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

}  // namespace vk

struct VulkanDevice::State {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties{};
  VkPhysicalDeviceMemoryProperties memory{};
  std::string driver_name, driver_info;
  uint32_t queue_family = 0;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
  VulkanSettings settings;
  bool validation_on = false;
  bool depth_clip_control = false;  // VK_EXT_depth_clip_control: GL's clip-space depth for raster passes
  std::string validation_why;
  DispatchBounds bounds;
  GlslangProcess glslang;
  mutable std::vector<std::string> messages;  // the validation layer's, since the last check
  mutable std::vector<PassOrigin> origins;     // --hlsl-root: what each stage compiled since ran from
  mutable std::set<std::string> copies_read;   // --hlsl-root: the copies' names read so far
  // Each stage compiled so far (vk/vulkan_stage_spirv.cpp), by what it was compiled from: a check
  // makes its passes afresh case by case, and the HLSL route (SPIRV-Cross, then glslang's HLSL
  // front end and legalization) costs the same text again every time. Not with --hlsl-root.
  struct CompiledStage {
    std::vector<std::uint32_t> spirv;
    std::vector<GuardedLoop> loops;
  };
  mutable std::map<std::string, CompiledStage> compiled;

  // A submission past its deadline (`check --gpu-timeout`). A Vulkan job cannot be cancelled:
  // lavapipe's worker threads go on running the shader, reading and writing every buffer, image,
  // descriptor set and pipeline its command buffer names. Freeing any of them under the running
  // job is what ended `check traversal --api vulkan --gpu-timeout 0.2` in SIGSEGV (the exception's
  // unwinding destroyed them), and any wait for the job (vkDeviceWaitIdle, vkDestroyDevice, even
  // vkGetFenceStatus on lavapipe) hangs as long as it runs: forever, on an endless loop. So from
  // the timeout on the device is *abandoned* and the process waits for the job on no call of its
  // own:
  // - nothing made on the device is destroyed: every destructor of the executor returns first while
  //   `abandoned()`, and the objects leak, deliberately (the job may still be reading them);
  // - the fence waiter (its own thread) goes on waiting for the job; the next use of the device
  //   (ensure_usable) gives it up to the deadline once more: if the job has ended by then, the
  //   device is whole again (what leaked stays leaked) and the checks go on; if not, the device is
  //   given up, and every later use fails at once, naming the stuck job, with no Vulkan call;
  // - ~State, while the job runs, destroys and waits for nothing (the device, the instance and the
  //   waiter, blocked in the driver, leak) and marks the process (vulkan_job_abandoned()):
  //   `penumbra` then ends by _Exit after its report, so no exit handler or static destructor can
  //   wait for the job's threads or free what they use (cli/main.cpp).
  mutable std::unique_ptr<vk::FenceWaiter> waiter;
  // One check's device time (start_budget): the seconds its submissions waited in all, bounded by
  // kBudgetFactor × the dispatch deadline. A copy whose loops the driver cuts short one dispatch at
  // a time (llvmpipe ends a loop silently at 65535 iterations, above a --loop-limit that high)
  // keeps every dispatch under the deadline and used to run a check for many minutes: past the
  // budget the check fails as a deadline fails.
  static constexpr double kBudgetFactor = 10;
  mutable double device_seconds = 0;
  mutable VkFence stuck_fence = VK_NULL_HANDLE;
  mutable VkCommandBuffer stuck_commands = VK_NULL_HANDLE;
  mutable std::string stuck_what;  // "passes/blur.comp: dispatch did not finish within 2 s"
  mutable bool given_up = false;
  bool abandoned() const { return stuck_fence != VK_NULL_HANDLE; }

  State() = default;
  State(const State&) = delete;
  State& operator=(const State&) = delete;
  ~State();

  // Throws Error(ExitCode::failed) with the first validation message since the last call.
  void throw_if_messages(const std::string& what) const;

  uint32_t memory_type(uint32_t bits, VkMemoryPropertyFlags flags) const;

  static bool& abandoned_jobs();

  double timeout_s() const { return bounds.enabled ? bounds.timeout_s : 3600.0; }

  // Whether the stuck job has ended, giving it up to `seconds` (its waiter's word: no Vulkan call
  // that could block); if it has, the device is whole again: its fence and command buffer are
  // freed, and destructors free what they own once more.
  bool stuck_job_ended(double seconds) const;

  // Before any use of the device (a submission, an object made): throws Error naming `what` and
  // the stuck job when a job past its deadline still runs (above).
  void ensure_usable(const std::string& what) const;

  // Records commands into a new command buffer, submits it and waits, under the dispatch
  // bounds' deadline. Throws Error naming `what` on a timeout or a validation message; after a
  // timeout the device is abandoned (above).
  void submit(const std::string& what, const std::function<void(VkCommandBuffer)>& record) const;
};

}  // namespace pn
