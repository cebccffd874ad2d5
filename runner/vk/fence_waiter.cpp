#include "vk/fence_waiter.h"

#include <chrono>
#include <cstdint>

namespace pn::vk {

FenceWaiter::FenceWaiter(VkDevice device) : device_(device), thread_([this] { loop(); }) {}

FenceWaiter::~FenceWaiter() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    quit_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void FenceWaiter::start(VkFence fence) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    fence_ = fence, done_ = false;
  }
  changed_.notify_all();
}

bool FenceWaiter::wait(double seconds, VkResult& result) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (!changed_.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return done_; })) return false;
  result = result_;
  return true;
}

void FenceWaiter::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return quit_ || fence_ != VK_NULL_HANDLE; });
    if (quit_) return;
    const VkFence fence = fence_;
    lock.unlock();
    const VkResult r = vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX);
    lock.lock();
    fence_ = VK_NULL_HANDLE, result_ = r, done_ = true;
    changed_.notify_all();
  }
}

}  // namespace pn::vk
