// The Vulkan executor's fence waiter: one fence at a time waited for on a thread of its own, so a
// submission's deadline holds on the runner's clock (vk/vulkan_state.h).
#pragma once

#include <vulkan/vulkan.h>

#include <condition_variable>
#include <mutex>
#include <thread>

namespace pn::vk {

// Waits for one fence at a time on a thread of its own, so that the caller's deadline holds on the
// runner's clock whatever the driver's wait does, and the calling thread never sits in a driver
// call that a job without end could block: lavapipe's vkWaitForFences was caught (gdb, `check blur
// --gpu-timeout 2` on a loaded machine) still in its timed wait seconds past its deadline, and its
// waits take locks its queue thread holds while it runs a job.
class FenceWaiter {
 public:
  explicit FenceWaiter(VkDevice device);
  FenceWaiter(const FenceWaiter&) = delete;
  FenceWaiter& operator=(const FenceWaiter&) = delete;
  // Only when no wait is in flight (State leaks a waiter still inside the driver, with its device).
  ~FenceWaiter();

  void start(VkFence fence);
  // Whether the fence last started has signalled, waiting up to `seconds`; `result`: the driver's.
  bool wait(double seconds, VkResult& result);

 private:
  void loop();

  VkDevice device_;
  std::mutex mutex_;
  std::condition_variable changed_;
  VkFence fence_ = VK_NULL_HANDLE;
  bool done_ = false, quit_ = false;
  VkResult result_ = VK_SUCCESS;
  std::thread thread_;  // last: it starts with the others made
};

}  // namespace pn::vk
