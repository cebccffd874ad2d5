#include "vk/vulkan_device.h"

#include <vulkan/vulkan.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <functional>
#include <list>
#include <mutex>
#include <set>
#include <thread>
#include <tuple>
#include <utility>

#include "core/error.h"
#include "core/format.h"
#include "passes/scene_raster.h"  // glsl/passes: the raster passes' vertex location
#include "shader/flatten.h"
#include "shader/glslang_compiler.h"
#include "shader/loop_guard.h"
#include "shader/spirv_cross.h"
#include "shader/target.h"
#include "vk/vulkan_pipeline_parts.h"

// Vulkan's create-info structs are named by their sType and then filled field by field.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace pn {

namespace {

// The storage buffer of the loop guard (shader/loop_guard.h) on Vulkan: below the HLSL samplers'
// shifted bindings, above every pass's own.
constexpr unsigned kGuardBinding = kHlslSamplerBindingShift - 1;

std::string version_text(uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
         std::to_string(VK_API_VERSION_PATCH(v));
}

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

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


// Waits for one fence at a time on a thread of its own, so that the caller's deadline holds on the
// runner's clock whatever the driver's wait does, and the calling thread never sits in a driver
// call that a job without end could block: lavapipe's vkWaitForFences was caught (gdb, `check blur
// --gpu-timeout 2` on a loaded machine) still in its timed wait seconds past its deadline, and its
// waits take locks its queue thread holds while it runs a job.
class FenceWaiter {
 public:
  explicit FenceWaiter(VkDevice device) : device_(device), thread_([this] { loop(); }) {}
  FenceWaiter(const FenceWaiter&) = delete;
  FenceWaiter& operator=(const FenceWaiter&) = delete;
  // Only when no wait is in flight (State leaks a waiter still inside the driver, with its device).
  ~FenceWaiter() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      quit_ = true;
    }
    changed_.notify_all();
    thread_.join();
  }

  void start(VkFence fence) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      fence_ = fence, done_ = false;
    }
    changed_.notify_all();
  }
  // Whether the fence last started has signalled, waiting up to `seconds`; `result`: the driver's.
  bool wait(double seconds, VkResult& result) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!changed_.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return done_; })) return false;
    result = result_;
    return true;
  }

 private:
  void loop() {
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

  VkDevice device_;
  std::mutex mutex_;
  std::condition_variable changed_;
  VkFence fence_ = VK_NULL_HANDLE;
  bool done_ = false, quit_ = false;
  VkResult result_ = VK_SUCCESS;
  std::thread thread_;  // last: it starts with the others made
};

}  // namespace

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

  // A submission past its deadline (`check --gpu-timeout`). A Vulkan job cannot be cancelled:
  // lavapipe's worker threads go on running the shader, reading and writing every buffer, image,
  // descriptor set and pipeline its command buffer names. Freeing any of them under the running
  // job is what ended `check traversal --api vulkan --gpu-timeout 0.2` in SIGSEGV (the exception's
  // unwinding destroyed them), and any wait for the job (vkDeviceWaitIdle, vkDestroyDevice, even
  // vkGetFenceStatus on lavapipe) hangs as long as it runs: forever, on an endless loop. So from
  // the timeout on the device is *abandoned* and the process waits for the job on no call of its
  // own:
  // - nothing made on the device is destroyed: every destructor below returns first while
  //   `abandoned()`, and the objects leak, deliberately (the job may still be reading them);
  // - the fence waiter (its own thread) goes on waiting for the job; the next use of the device
  //   (ensure_usable) gives it up to the deadline once more: if the job has ended by then, the
  //   device is whole again (what leaked stays leaked) and the checks go on; if not, the device is
  //   given up, and every later use fails at once, naming the stuck job, with no Vulkan call;
  // - ~State, while the job runs, destroys and waits for nothing (the device, the instance and the
  //   waiter, blocked in the driver, leak) and marks the process (vulkan_job_abandoned()):
  //   `penumbra` then ends by _Exit after its report, so no exit handler or static destructor can
  //   wait for the job's threads or free what they use (cli/main.cpp).
  mutable std::unique_ptr<FenceWaiter> waiter;
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
  ~State() {
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

  // Throws Error(ExitCode::failed) with the first validation message since the last call.
  void throw_if_messages(const std::string& what) const {
    if (messages.empty()) return;
    std::string first = messages.front();
    const size_t more = messages.size() - 1;
    messages.clear();
    throw Error(what + ": Vulkan validation: " + first + (more ? " (and " + std::to_string(more) + " more)" : ""),
                ExitCode::failed);
  }

  uint32_t memory_type(uint32_t bits, VkMemoryPropertyFlags flags) const {
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
      if ((bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
    throw Error("vulkan: no memory type with the properties a buffer or image needs", ExitCode::failed);
  }

  static bool& abandoned_jobs() {
    static bool any = false;
    return any;
  }

  double timeout_s() const { return bounds.enabled ? bounds.timeout_s : 3600.0; }

  // Whether the stuck job has ended, giving it up to `seconds` (its waiter's word: no Vulkan call
  // that could block); if it has, the device is whole again: its fence and command buffer are
  // freed, and destructors free what they own once more.
  bool stuck_job_ended(double seconds) const {
    VkResult result = VK_SUCCESS;
    if (!waiter->wait(seconds, result)) return false;
    vkDestroyFence(device, stuck_fence, nullptr);
    vkFreeCommandBuffers(device, pool, 1, &stuck_commands);
    stuck_fence = VK_NULL_HANDLE, stuck_commands = VK_NULL_HANDLE, stuck_what.clear();
    return true;
  }

  // Before any use of the device (a submission, an object made): throws Error naming `what` and
  // the stuck job when a job past its deadline still runs (above).
  void ensure_usable(const std::string& what) const {
    if (!abandoned()) return;
    if (!given_up && stuck_job_ended(timeout_s())) return;
    given_up = true;
    throw Error(what + ": not run: the Vulkan device still runs the job that " + stuck_what +
                    " (a Vulkan job cannot be cancelled)",
                ExitCode::failed);
  }

  // Records commands into a new command buffer, submits it and waits, under the dispatch
  // bounds' deadline. Throws Error naming `what` on a timeout or a validation message; after a
  // timeout the device is abandoned (above).
  void submit(const std::string& what, const std::function<void(VkCommandBuffer)>& record) const {
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
      // Still running: its commands and fence are kept, and so is everything it reads (above).
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
};

namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                     VkDebugUtilsMessageTypeFlagsEXT,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data, void* state) {
  static_cast<const VulkanDevice::State*>(state)->messages.push_back(data->pMessage ? data->pMessage : "?");
  return VK_FALSE;
}

// A host-visible, coherent buffer, mapped for its life.
class HostBuffer {
 public:
  HostBuffer(const VulkanDevice::State& s, VkDeviceSize size, VkBufferUsageFlags usage) : s_(&s), size_(size) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = std::max<VkDeviceSize>(size, 4);
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    vk_check(vkCreateBuffer(s.device, &info, nullptr, &buffer_), "creating a buffer");
    VkMemoryRequirements needs;
    vkGetBufferMemoryRequirements(s.device, buffer_, &needs);
    VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocate.allocationSize = needs.size;
    allocate.memoryTypeIndex =
        s.memory_type(needs.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    vk_check(vkAllocateMemory(s.device, &allocate, nullptr, &memory_), "allocating buffer memory");
    vk_check(vkBindBufferMemory(s.device, buffer_, memory_, 0), "binding buffer memory");
    vk_check(vkMapMemory(s.device, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "mapping a buffer");
  }
  ~HostBuffer() {
    if (s_->abandoned()) return;  // a stuck job may read it (State)
    if (memory_ != VK_NULL_HANDLE) vkFreeMemory(s_->device, memory_, nullptr);  // unmaps
    if (buffer_ != VK_NULL_HANDLE) vkDestroyBuffer(s_->device, buffer_, nullptr);
  }
  HostBuffer(const HostBuffer&) = delete;
  HostBuffer& operator=(const HostBuffer&) = delete;
  VkBuffer buffer() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  void* data() const { return mapped_; }

 private:
  const VulkanDevice::State* s_;
  VkDeviceSize size_;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  void* mapped_ = nullptr;
};

// Device-local memory for `image`, bound to it.
VkDeviceMemory bind_image_memory(const VulkanDevice::State& s, VkImage image, const std::string& what) {
  VkMemoryRequirements needs;
  vkGetImageMemoryRequirements(s.device, image, &needs);
  VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocate.allocationSize = needs.size;
  allocate.memoryTypeIndex = s.memory_type(needs.memoryTypeBits, 0);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  vk_check(vkAllocateMemory(s.device, &allocate, nullptr, &memory), "allocating " + what);
  const VkResult bound = vkBindImageMemory(s.device, image, memory, 0);
  if (bound != VK_SUCCESS) vkFreeMemory(s.device, memory, nullptr);
  vk_check(bound, "binding " + what);
  return memory;
}

// Every image stays in GENERAL layout from its upload on: a pass samples one level of a chain while
// it writes the next as a storage image, and results are read back from it.
constexpr VkImageLayout kImageLayout = VK_IMAGE_LAYOUT_GENERAL;

void image_barrier(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                   VkAccessFlags src_access, VkAccessFlags dst_access, VkPipelineStageFlags src_stage,
                   VkPipelineStageFlags dst_stage) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcAccessMask = src_access;
  barrier.dstAccessMask = dst_access;
  barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
  vkCmdPipelineBarrier(commands, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

VkFormat vk_format(TexelFormat format) {
  switch (format) {
    case TexelFormat::r32f: return VK_FORMAT_R32_SFLOAT;
    case TexelFormat::rg32f: return VK_FORMAT_R32G32_SFLOAT;
    case TexelFormat::rgba32f: return VK_FORMAT_R32G32B32A32_SFLOAT;
    case TexelFormat::rgba32ui: return VK_FORMAT_R32G32B32A32_UINT;
  }
  return VK_FORMAT_R32G32B32A32_SFLOAT;
}

std::string shape_text(const TextureShape& shape) {
  return std::to_string(shape.width) + "x" + std::to_string(shape.height) + " (" + std::to_string(shape.levels) +
         " levels, " + std::to_string(shape.layers) + " layers)";
}

}  // namespace

// A 2-D image (or 2-D array) of some levels on the device, in GENERAL layout: a view of every
// level and layer to sample, and one a level to write as a storage image.
class VulkanImage final : public DeviceTexture {
 public:
  VulkanImage(const VulkanDevice::State& s, const TextureShape& shape) : DeviceTexture(shape), s_(&s) {
    const VkFormat format = vk_format(shape.format);
    VkImageFormatProperties limits{};
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                    VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    const VkResult supported = vkGetPhysicalDeviceImageFormatProperties(
        s.physical, format, VK_IMAGE_TYPE_2D, VK_IMAGE_TILING_OPTIMAL, usage, 0, &limits);
    int full_levels = 1;
    while ((std::max(shape.width, shape.height) >> full_levels) > 0) ++full_levels;
    if (supported != VK_SUCCESS || shape.width < 1 || shape.height < 1 ||
        static_cast<uint32_t>(shape.width) > limits.maxExtent.width ||
        static_cast<uint32_t>(shape.height) > limits.maxExtent.height || shape.layers < 1 ||
        static_cast<uint32_t>(shape.layers) > limits.maxArrayLayers || (shape.layers > 1 && !shape.array) ||
        shape.levels < 1 || shape.levels > full_levels)
      throw Error("vulkan: a texture of " + shape_text(shape) + ": expected sides 1.." +
                      std::to_string(limits.maxExtent.width) + ", 1.." + std::to_string(limits.maxArrayLayers) +
                      " layers (an array for more than one), 1.." + std::to_string(full_levels) +
                      " levels, and a format the device samples and stores",
                  ExitCode::failed);
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {static_cast<uint32_t>(shape.width), static_cast<uint32_t>(shape.height), 1};
    info.mipLevels = static_cast<uint32_t>(shape.levels);
    info.arrayLayers = static_cast<uint32_t>(shape.layers);
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    vk_check(vkCreateImage(s.device, &info, nullptr, &image_), "creating a " + shape_text(shape) + " image");
    memory_ = bind_image_memory(s, image_, "image memory");
    view_ = make_view(0, shape.levels);
    for (int level = 0; level < shape.levels; ++level) level_views_.push_back(make_view(level, 1));
  }
  ~VulkanImage() override {
    if (s_->abandoned()) return;  // a stuck job may read it (State)
    for (VkImageView view : level_views_) vkDestroyImageView(s_->device, view, nullptr);
    if (view_ != VK_NULL_HANDLE) vkDestroyImageView(s_->device, view_, nullptr);
    if (image_ != VK_NULL_HANDLE) vkDestroyImage(s_->device, image_, nullptr);
    if (memory_ != VK_NULL_HANDLE) vkFreeMemory(s_->device, memory_, nullptr);
  }
  const VulkanDevice::State* owner() const { return s_; }
  VkImage image() const { return image_; }
  VkImageView view() const { return view_; }                                   // every level and layer
  VkImageView level_view(int level) const { return level_views_[static_cast<size_t>(level)]; }  // every layer
  bool integer() const { return shape().format == TexelFormat::rgba32ui; }

  // Fills level 0 of layer 0 with `bytes` (tightly packed texels of its format), or every texel
  // with zeros, and leaves the image in GENERAL layout.
  void fill(const void* bytes, std::size_t size) const {
    const std::optional<HostBuffer> staging =
        bytes ? std::optional<HostBuffer>(std::in_place, *s_, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT) : std::nullopt;
    if (staging) std::memcpy(staging->data(), bytes, size);
    s_->submit("uploading an image", [&](VkCommandBuffer c) {
      image_barrier(c, image_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                    VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
      if (staging) {
        const VkBufferImageCopy copy = region(0, 0);
        vkCmdCopyBufferToImage(c, staging->buffer(), image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
      } else {
        const VkClearColorValue zero{};
        const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0,
                                            VK_REMAINING_ARRAY_LAYERS};
        vkCmdClearColorImage(c, image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
      }
      image_barrier(c, image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kImageLayout, VK_ACCESS_TRANSFER_WRITE_BIT,
                    VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
    });
  }

  // The texels of one level and layer back, texel_channels(format) words a texel.
  std::vector<std::uint32_t> read(int level, int layer) const {
    const TextureShape& shape = this->shape();
    if (level < 0 || level >= shape.levels || layer < 0 || layer >= shape.layers)
      throw Error("vulkan: reading level " + std::to_string(level) + ", layer " + std::to_string(layer) +
                      " of a texture of " + shape_text(shape),
                  ExitCode::failed);
    const std::size_t words = static_cast<std::size_t>(shape.level_width(level)) * shape.level_height(level) *
                              static_cast<std::size_t>(texel_channels(shape.format));
    const HostBuffer staging(*s_, words * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    s_->submit("reading a texture back", [&](VkCommandBuffer c) {
      image_barrier(c, image_, kImageLayout, kImageLayout, VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT,
                    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
      const VkBufferImageCopy copy = region(level, layer);
      vkCmdCopyImageToBuffer(c, image_, kImageLayout, staging.buffer(), 1, &copy);
      VkMemoryBarrier host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
      host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &host, 0, nullptr, 0,
                           nullptr);
    });
    std::vector<std::uint32_t> out(words);
    std::memcpy(out.data(), staging.data(), words * 4);
    return out;
  }

 private:
  VkImageView make_view(int first_level, int levels) const {
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image_;
    view.viewType = shape().array ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
    view.format = vk_format(shape().format);
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, static_cast<uint32_t>(first_level),
                             static_cast<uint32_t>(levels), 0, static_cast<uint32_t>(shape().layers)};
    VkImageView out = VK_NULL_HANDLE;
    vk_check(vkCreateImageView(s_->device, &view, nullptr, &out), "creating an image view");
    return out;
  }
  VkBufferImageCopy region(int level, int layer) const {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, static_cast<uint32_t>(level), static_cast<uint32_t>(layer), 1};
    copy.imageExtent = {static_cast<uint32_t>(shape().level_width(level)),
                        static_cast<uint32_t>(shape().level_height(level)), 1};
    return copy;
  }

  const VulkanDevice::State* s_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  std::vector<VkImageView> level_views_;
};

namespace {

// A storage buffer: host-visible, so a write is a copy into its mapping.
class VulkanBuffer final : public DeviceBuffer {
 public:
  VulkanBuffer(const VulkanDevice::State& s, std::size_t bytes)
      : buffer_(s, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT), owner_(&s) {}
  const HostBuffer& host() const { return buffer_; }
  const VulkanDevice::State* owner() const { return owner_; }

 private:
  HostBuffer buffer_;
  const VulkanDevice::State* owner_;
};

std::unique_ptr<VulkanImage> upload_image(const VulkanDevice::State& s, const Image& image) {
  if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4)
    throw Error("vulkan: an image of " + std::to_string(image.width) + "x" + std::to_string(image.height) + "x" +
                    std::to_string(image.channels) + ": expected a positive size and 1 to 4 channels",
                ExitCode::failed);
  // 3 channels go up as 4, alpha 1 (GL's RGB32F reads).
  const TextureShape shape = float_shape(image.width, image.height, image.channels);
  const int channels = texel_channels(shape.format);
  std::vector<float> texels(static_cast<std::size_t>(image.width) * image.height * channels, 1.0f);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < image.channels; ++c)
        texels[(static_cast<std::size_t>(y) * image.width + x) * channels + c] = image.at(x, y, c);
  auto out = std::make_unique<VulkanImage>(s, shape);
  out->fill(texels.data(), texels.size() * sizeof(float));
  return out;
}

Image float_image(const std::vector<std::uint32_t>& words, int width, int height, int channels) {
  Image image(width, height, channels);
  std::memcpy(image.texels.data(), words.data(), words.size() * 4);
  return image;
}

class VulkanQueryBatch final : public QueryBatch {
 public:
  VulkanQueryBatch(const VulkanDevice::State& s, const std::vector<Image>& inputs, std::size_t results,
                   std::size_t word_results) {
    std::tie(width_, height_) = query_batch_size(inputs);
    for (const Image& input : inputs) inputs_.push_back(upload_image(s, input));
    for (std::size_t i = 0; i < results + word_results; ++i) {
      const TexelFormat format = i < results ? TexelFormat::rgba32f : TexelFormat::rgba32ui;
      auto image = std::make_unique<VulkanImage>(s, TextureShape{format, width_, height_});
      image->fill(nullptr, 0);
      (i < results ? results_ : word_results_).push_back(std::move(image));
    }
  }
  int width() const override { return width_; }
  int height() const override { return height_; }
  std::size_t inputs() const override { return inputs_.size(); }
  std::size_t results() const override { return results_.size(); }
  std::size_t word_results() const override { return word_results_.size(); }
  QueryResults read() const override {
    QueryResults out;
    for (const auto& result : results_) out.images.push_back(float_image(result->read(0, 0), width_, height_, 4));
    for (const auto& result : word_results_) out.words.push_back(result->read(0, 0));
    return out;
  }

  std::vector<std::unique_ptr<VulkanImage>> inputs_, results_, word_results_;

 private:
  int width_ = 0, height_ = 0;
};

// The resources of one dispatch or draw in a descriptor set of its own (a pool a set), with the
// uniform block's buffer and the loop guard's.
struct BoundSet {
  const VulkanDevice::State* s = nullptr;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
  std::list<HostBuffer> uniforms;  // one a uniform block
  std::optional<HostBuffer> guard;
  BoundSet() = default;
  BoundSet(const BoundSet&) = delete;
  BoundSet& operator=(const BoundSet&) = delete;
  ~BoundSet() {
    if (s == nullptr || s->abandoned()) return;  // a stuck job may read it (State)
    if (pool != VK_NULL_HANDLE) vkDestroyDescriptorPool(s->device, pool, nullptr);
  }
};

// What a compute and a raster program share: a name, the resources its SPIR-V uses (every stage's),
// their set layout, the pipeline layout and the pipeline.
class VulkanProgram : public QueryProgram {
 public:
  ~VulkanProgram() override {
    if (s_->abandoned()) return;  // a stuck job may run it (State)
    for (VkShaderModule module : modules_) vkDestroyShaderModule(s_->device, module, nullptr);
    if (pipeline_ != VK_NULL_HANDLE) vkDestroyPipeline(s_->device, pipeline_, nullptr);
    if (pipeline_layout_ != VK_NULL_HANDLE) vkDestroyPipelineLayout(s_->device, pipeline_layout_, nullptr);
    if (set_layout_ != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(s_->device, set_layout_, nullptr);
  }

 protected:
  // `stages`: each stage's SPIR-V and its stage bit; a resource two stages use is one binding.
  VulkanProgram(const VulkanDevice::State& s, std::string name,
                const std::vector<std::pair<const std::vector<std::uint32_t>*, VkShaderStageFlagBits>>& stages)
      : s_(&s), name_(std::move(name)) {
    for (const auto& [spirv, stage] : stages) modules_.push_back(make_shader_module(s.device, *spirv, name_));
    SetLayoutBindings set = set_layout_bindings(stages, name_);
    bindings_ = std::move(set.bindings);
    std::copy(std::begin(set.local_size), std::end(set.local_size), local_size_);
    const std::vector<VkDescriptorSetLayoutBinding>& layout = set.layout;
    VkDescriptorSetLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    layout_info.bindingCount = static_cast<uint32_t>(layout.size());
    layout_info.pBindings = layout.data();
    vk_check(vkCreateDescriptorSetLayout(s.device, &layout_info, nullptr, &set_layout_), name_ + ": a set layout");
    VkPipelineLayoutCreateInfo pipeline_layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pipeline_layout_info.setLayoutCount = 1;
    pipeline_layout_info.pSetLayouts = &set_layout_;
    vk_check(vkCreatePipelineLayout(s.device, &pipeline_layout_info, nullptr, &pipeline_layout_),
             name_ + ": a pipeline layout");
  }

  // A descriptor set holding `resources` at the bindings the SPIR-V uses (and the loop guard's
  // buffer, cleared, where it has one). Throws Error naming a resource it uses and `resources`
  // lacks, or one made on another device.
  void bind(const PassResources& resources, BoundSet& out) const;

  template <class Made>
  const Made& made_here(const auto& object, unsigned binding) const {
    const auto* made = dynamic_cast<const Made*>(&object);
    if (made == nullptr || made->owner() != s_)
      throw Error(name_ + ": the resource at binding " + std::to_string(binding) + " was made on another device",
                  ExitCode::failed);
    return *made;
  }

  const VulkanDevice::State* s_;
  std::string name_;
  std::vector<SpirvBinding> bindings_;
  std::vector<VkShaderModule> modules_;
  unsigned local_size_[3] = {1, 1, 1};
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
};

void VulkanProgram::bind(const PassResources& resources, BoundSet& out) const {
  const VulkanDevice::State& s = *s_;
  out.s = s_;
  std::vector<VkDescriptorPoolSize> sizes;
  for (const SpirvBinding& b : bindings_) sizes.push_back({descriptor_type(b.kind), 1});
  if (sizes.empty()) return;
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = static_cast<uint32_t>(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  vk_check(vkCreateDescriptorPool(s.device, &pool_info, nullptr, &out.pool), name_ + ": a descriptor pool");
  VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocate.descriptorPool = out.pool;
  allocate.descriptorSetCount = 1;
  allocate.pSetLayouts = &set_layout_;
  vk_check(vkAllocateDescriptorSets(s.device, &allocate, &out.set), name_ + ": a descriptor set");

  std::vector<VkDescriptorImageInfo> images(bindings_.size());
  std::vector<VkDescriptorBufferInfo> buffers(bindings_.size());
  std::vector<VkWriteDescriptorSet> writes;
  for (std::size_t i = 0; i < bindings_.size(); ++i) {
    const SpirvBinding& b = bindings_[i];
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = out.set;
    write.dstBinding = b.binding;
    write.descriptorCount = 1;
    write.descriptorType = descriptor_type(b.kind);
    const std::string where = name_ + ": '" + b.name + "' (binding " + std::to_string(b.binding) + ")";
    switch (b.kind) {
      case DescriptorKind::combined_image_sampler:
      case DescriptorKind::sampled_image: {
        const auto t = std::find_if(resources.textures.begin(), resources.textures.end(),
                                    [&](const QueryTexture& t) { return t.binding == b.binding; });
        if (t == resources.textures.end())
          throw Error(where + " is a texture the dispatch does not give", ExitCode::failed);
        images[i] = {s.sampler, made_here<VulkanImage>(t->texture, b.binding).view(), kImageLayout};
        write.pImageInfo = &images[i];
        break;
      }
      case DescriptorKind::sampler:
        images[i] = {s.sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED};
        write.pImageInfo = &images[i];
        break;
      case DescriptorKind::storage_image: {
        const auto found = std::find_if(resources.images.begin(), resources.images.end(),
                                        [&](const PassImage& image) { return image.binding == b.binding; });
        if (found == resources.images.end())
          throw Error(where + " is an image the dispatch does not give", ExitCode::failed);
        const VulkanImage& image = made_here<VulkanImage>(found->texture, b.binding);
        if (image.integer() != b.integer)
          throw Error(where + " is an image of " + (b.integer ? "integer" : "float") + " texels: the dispatch gives " +
                          (image.integer() ? "RGBA32UI" : "floats"),
                      ExitCode::failed);
        if (found->level < 0 || found->level >= image.shape().levels)
          throw Error(where + ": level " + std::to_string(found->level) + " of a texture of " +
                          std::to_string(image.shape().levels) + " levels",
                      ExitCode::failed);
        images[i] = {VK_NULL_HANDLE, image.level_view(found->level), kImageLayout};
        write.pImageInfo = &images[i];
        break;
      }
      case DescriptorKind::uniform_buffer: {
        const std::vector<QueryBlock> blocks = uniform_blocks(resources);
        const auto block = std::find_if(blocks.begin(), blocks.end(),
                                        [&](const QueryBlock& block) { return block.binding == b.binding; });
        if (block == blocks.end())
          throw Error(where + " is a uniform block the dispatch does not give", ExitCode::failed);
        HostBuffer& uniform = out.uniforms.emplace_back(s, block->size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        std::memcpy(uniform.data(), block->data, block->size);
        buffers[i] = {uniform.buffer(), 0, block->size};
        write.pBufferInfo = &buffers[i];
        break;
      }
      case DescriptorKind::storage_buffer:
        if (b.binding == kGuardBinding) {
          out.guard.emplace(s, sizeof(LoopGuardState), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
          std::memset(out.guard->data(), 0, sizeof(LoopGuardState));
          buffers[i] = {out.guard->buffer(), 0, sizeof(LoopGuardState)};
        } else {
          const auto found = std::find_if(resources.buffers.begin(), resources.buffers.end(),
                                          [&](const PassBuffer& buffer) { return buffer.binding == b.binding; });
          if (found == resources.buffers.end())
            throw Error(where + " is a storage buffer the dispatch does not give", ExitCode::failed);
          const HostBuffer& buffer = made_here<VulkanBuffer>(found->buffer, b.binding).host();
          buffers[i] = {buffer.buffer(), 0, VK_WHOLE_SIZE};
        }
        write.pBufferInfo = &buffers[i];
        break;
    }
    writes.push_back(write);
  }
  vkUpdateDescriptorSets(s.device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

class VulkanQueryProgram final : public VulkanProgram {
 public:
  VulkanQueryProgram(const VulkanDevice::State& s, std::string name, const std::vector<std::uint32_t>& spirv,
                     std::vector<GuardedLoop> loops)
      : VulkanProgram(s, std::move(name), {{&spirv, VK_SHADER_STAGE_COMPUTE_BIT}}), loops_(std::move(loops)) {
    VkComputePipelineCreateInfo pipeline_info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pipeline_info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    pipeline_info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipeline_info.stage.module = modules_.front();
    pipeline_info.stage.pName = "main";
    pipeline_info.layout = pipeline_layout_;
    vk_check(vkCreateComputePipelines(s.device, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, &pipeline_),
             name_ + ": a compute pipeline");
    s.throw_if_messages(name_);
  }

  // Binds `resources` (the loop guard besides, under bounds) and runs the pass over a width ×
  // height grid of invocations, or (`groups`) over the work groups counted in that buffer.
  void run(const PassResources& resources, int width, int height, const DispatchBounds& bounds,
           const HostBuffer* groups = nullptr) const;

 private:
  std::vector<GuardedLoop> loops_;
};

void VulkanQueryProgram::run(const PassResources& resources, int width, int height, const DispatchBounds& bounds,
                             const HostBuffer* groups) const {
  if (groups == nullptr && (width <= 0 || height <= 0)) return;
  const VulkanDevice::State& s = *s_;
  BoundSet bound;
  bind(resources, bound);
  const auto group_count = [](int n, unsigned local) { return static_cast<uint32_t>((n + local - 1) / local); };
  s.submit(name_ + ": dispatch", [&](VkCommandBuffer c) {
    VkMemoryBarrier before{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    before.srcAccessMask = VK_ACCESS_HOST_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    before.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_UNIFORM_READ_BIT |
                           VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
    vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT, 0, 1, &before, 0,
                         nullptr, 0, nullptr);
    vkCmdBindPipeline(c, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    if (bound.set != VK_NULL_HANDLE)
      vkCmdBindDescriptorSets(c, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &bound.set, 0, nullptr);
    if (groups != nullptr)
      vkCmdDispatchIndirect(c, groups->buffer(), 0);
    else
      vkCmdDispatch(c, group_count(width, local_size_[0]), group_count(height, local_size_[1]), 1);
    VkMemoryBarrier after{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    after.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    after.dstAccessMask = VK_ACCESS_HOST_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_SHADER_READ_BIT;
    vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         0, 1, &after, 0, nullptr, 0, nullptr);
  });
  if (!bound.guard) return;
  LoopGuardState state;
  std::memcpy(&state, bound.guard->data(), sizeof state);
  throw_if_loop_tripped(state, loops_, bounds.loop_iterations, name_ + ": dispatch");
}


// A D32_SFLOAT depth attachment, kept in GENERAL layout (cleared, copied and drawn into as the
// colour is).
class DepthImage {
 public:
  DepthImage(const VulkanDevice::State& s, int size) : s_(&s) {
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
  ~DepthImage() {
    if (s_->abandoned()) return;  // a stuck job may write it (State)
    if (view_ != VK_NULL_HANDLE) vkDestroyImageView(s_->device, view_, nullptr);
    if (image_ != VK_NULL_HANDLE) vkDestroyImage(s_->device, image_, nullptr);
    if (memory_ != VK_NULL_HANDLE) vkFreeMemory(s_->device, memory_, nullptr);
  }
  DepthImage(const DepthImage&) = delete;
  DepthImage& operator=(const DepthImage&) = delete;
  VkImage image() const { return image_; }
  VkImageView view() const { return view_; }

 private:
  const VulkanDevice::State* s_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
};

// The render pass every raster draw runs in: a colour attachment of `format` and a D32 depth
// attachment, both loaded and stored in GENERAL layout (a target keeps what it holds between
// draws). Pipelines made with it draw in any target of the same format (render pass compatibility).
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

// A triangle list in a host-visible vertex buffer.
class VulkanVertices final : public DeviceVertices {
 public:
  VulkanVertices(const VulkanDevice::State& s, const std::vector<glm::vec3>& vertices)
      : DeviceVertices(static_cast<int>(vertices.size())),
        buffer_(s, std::max<std::size_t>(vertices.size(), 1) * sizeof(glm::vec3), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT),
        owner_(&s) {
    if (!vertices.empty()) std::memcpy(buffer_.data(), vertices.data(), vertices.size() * sizeof(glm::vec3));
  }
  const HostBuffer& buffer() const { return buffer_; }
  const VulkanDevice::State* owner() const { return owner_; }

 private:
  HostBuffer buffer_;
  const VulkanDevice::State* owner_;
};

// A colour image and its depth buffer, with the render pass and framebuffer that draw into them.
class VulkanRasterTarget final : public DeviceRasterTarget {
 public:
  VulkanRasterTarget(const VulkanDevice::State& s, int size, TexelFormat format)
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
  ~VulkanRasterTarget() override {
    if (s_->abandoned()) return;  // a stuck job may draw into it (State)
    if (framebuffer_ != VK_NULL_HANDLE) vkDestroyFramebuffer(s_->device, framebuffer_, nullptr);
    if (render_pass_ != VK_NULL_HANDLE) vkDestroyRenderPass(s_->device, render_pass_, nullptr);
  }
  const DeviceTexture& texture() const override { return *colour_; }
  const VulkanDevice::State* owner() const { return s_; }
  const VulkanImage& colour() const { return *colour_; }
  std::unique_ptr<VulkanImage> take_colour() { return std::move(colour_); }
  const DepthImage& depth() const { return depth_; }

  // Records `inside` between the beginning and the end of this target's render pass, the
  // viewport on the whole target (NDC y = -1 at row 0, as GL's: texels lie where GL's lie).
  void record_pass(VkCommandBuffer c, const std::function<void()>& inside) const {
    const uint32_t side = static_cast<uint32_t>(size());
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = render_pass_;
    begin.framebuffer = framebuffer_;
    begin.renderArea = {{0, 0}, {side, side}};
    vkCmdBeginRenderPass(c, &begin, VK_SUBPASS_CONTENTS_INLINE);
    inside();
    vkCmdEndRenderPass(c);
  }

 private:
  const VulkanDevice::State* s_;
  std::unique_ptr<VulkanImage> colour_;
  DepthImage depth_;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
};

// The rectangles a scissored operation covers: each one clipped to the target, the empty ones
// dropped; the whole target for none given.
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

// A vertex + fragment program drawing triangle lists into a target with a depth buffer, in GL's
// conventions: clip-space depth -1..1 (VK_EXT_depth_clip_control) and NDC y = -1 at row 0, so its
// texels are where GL's raster pass puts them.
class VulkanRasterProgram final : public VulkanProgram {
 public:
  // `positions`: the vertex stage reads a world position a vertex (a triangle list); else it makes
  // its own (full_screen.vert: three vertices, no vertex input).
  VulkanRasterProgram(const VulkanDevice::State& s, std::string name, const std::vector<std::uint32_t>& vertex,
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
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
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
  ~VulkanRasterProgram() override {
    if (s_->abandoned()) return;  // a stuck job may run it (State)
    if (render_pass_ != VK_NULL_HANDLE) vkDestroyRenderPass(s_->device, render_pass_, nullptr);
  }
  TexelFormat target_format() const { return target_; }

  // Draws `runs` of `vertices` (a program with positions) or its own full-screen triangle (one
  // without: `vertices` null) into `target` over what it holds, scissored to each rectangle.
  void draw(const VulkanVertices* vertices, const std::vector<VertexRun>& runs, const VulkanRasterTarget& target,
            const std::vector<TexelRect>& rects, const PassResources& resources) const {
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
        if (bound.set != VK_NULL_HANDLE)
          vkCmdBindDescriptorSets(c, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_layout_, 0, 1, &bound.set, 0, nullptr);
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

 private:
  TexelFormat target_;
  bool positions_;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
};

// `clear` into `target` inside each rectangle (the whole target for none), depth to the far plane.
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

}  // namespace

VulkanDevice::VulkanDevice(std::unique_ptr<State> state) : state_(std::move(state)) {}
VulkanDevice::~VulkanDevice() = default;

std::string VulkanDevice::device_name() const { return state_->properties.deviceName; }
std::string VulkanDevice::driver() const {
  return state_->driver_name + (state_->driver_info.empty() ? "" : ", " + state_->driver_info);
}
std::string VulkanDevice::api_version() const { return version_text(state_->properties.apiVersion); }
std::string VulkanDevice::device_type() const {
  switch (state_->properties.deviceType) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
    default: return "other";
  }
}
std::string VulkanDevice::validation() const {
  return state_->validation_on ? std::string("on (") + kValidationLayer + ")" : "off (" + state_->validation_why + ")";
}
void VulkanDevice::set_dispatch_bounds(const DispatchBounds& bounds) { state_->bounds = bounds; }
void VulkanDevice::start_budget() { state_->device_seconds = 0; }

std::vector<PassOrigin> VulkanDevice::take_pass_origins() const { return std::exchange(state_->origins, {}); }

std::vector<std::string> VulkanDevice::hlsl_copies_read() const {
  return {state_->copies_read.begin(), state_->copies_read.end()};
}

std::string VulkanDevice::query_api() const {
  return state_->settings.language == PassLanguage::hlsl ? "hlsl" : "vulkan";
}

namespace {

// One stage of a pass as the device runs it: the vulkan target's SPIR-V, or (--api hlsl) its HLSL
// export compiled back — or the user's copy of that export (--hlsl-root, a pass without extra
// defines). `loops`: the loop guard's loops, put in under the dispatch bounds (compute passes):
// into the GLSL, which the library's HLSL export is made from, or into the user's copy.
std::vector<std::uint32_t> stage_spirv(const VulkanDevice::State& s, const SourceTree& tree, const std::string& pass,
                                       const std::vector<Define>& defines, std::vector<GuardedLoop>* loops) {
  ShaderSource source = standalone_source(flatten(tree, tree.locate_in_root(pass)), Target::vulkan, defines);
  if (loops != nullptr && s.bounds.enabled)
    *loops = guard_loops(s.glslang, source, Target::vulkan, {kGuardBinding, s.bounds.loop_iterations});
  const CompileResult glsl = compile_with_glslang(s.glslang, source, Target::vulkan);
  if (!glsl.ok) throw Error(pass + ": " + first_error(glsl, "glslang could not compile it for Vulkan"), ExitCode::failed);
  if (s.settings.language == PassLanguage::glsl) return glsl.spirv;

  std::string name = std::filesystem::path(pass).stem().string() + ".hlsl";
  std::string hlsl;
  // The copy stands in for the entry of its name (vk/hlsl_root.h); either way, what ran is recorded
  // for the check's report, so a check never falls back to the library's export in silence.
  const std::filesystem::path copy = s.settings.hlsl_root ? *s.settings.hlsl_root / name : std::filesystem::path();
  const bool has_copy = s.settings.hlsl_root && std::filesystem::is_regular_file(copy);  // links followed
  if (source.stage == Stage::compute && has_copy && defines.empty()) {
    const SourceTree root(*s.settings.hlsl_root);  // read as module files are: a regular file, bounded
    const std::filesystem::path canonical = root.locate_in_root(name);
    hlsl = root.read(canonical), name = root.diagnostic_path(canonical);
    if (loops != nullptr)  // the copy's own loops, guarded as the GLSL's are
      *loops = s.bounds.enabled ? guard_hlsl_loops(s.glslang, hlsl, name, source.stage,
                                                   {kGuardBinding, s.bounds.loop_iterations})
                                : std::vector<GuardedLoop>{};
    s.origins.push_back({pass, name, "", ""});
    s.copies_read.insert(copy.filename().string());
  } else {
    hlsl = cross_compile(glsl.spirv, CrossLanguage::hlsl50);
    if (s.settings.hlsl_root) {
      const std::string root = s.settings.hlsl_root->string();
      if (source.stage != Stage::compute) {
        s.origins.push_back({pass, "", "vertex and fragment stages (a copy stands in for a compute entry only)", ""});
      } else if (!defines.empty()) {
        std::string set;
        for (const Define& d : defines) set += (set.empty() ? "" : " ") + d.name + (d.value.empty() ? "" : "=" + d.value);
        s.origins.push_back({pass, "",
                             std::string("compiled with defines, which a copy (one fixed text) cannot take") +
                                 (has_copy ? ": its copy in " + root + " not read" : ""),
                             set});
      } else {
        s.origins.push_back({pass, "", "no copy of it in " + root, ""});
      }
    }
  }
  const CompileResult back = compile_hlsl_with_glslang(s.glslang, hlsl, name, source.stage);
  if (!back.ok) throw Error(name + ": " + first_error(back, "glslang could not compile the HLSL"), ExitCode::failed);
  return back.spirv;
}

std::string program_name(const VulkanDevice::State& s, const std::string& pass) {
  return s.settings.language == PassLanguage::hlsl ? pass + " (HLSL)" : pass;
}

}  // namespace

std::unique_ptr<QueryProgram> VulkanDevice::compile_query(const SourceTree& tree, const std::string& pass,
                                                          const std::vector<Define>& defines) const {
  state_->ensure_usable(pass);
  std::vector<GuardedLoop> loops;
  const std::vector<std::uint32_t> spirv = stage_spirv(*state_, tree, pass, defines, &loops);
  return std::make_unique<VulkanQueryProgram>(*state_, program_name(*state_, pass), spirv, std::move(loops));
}

std::unique_ptr<QueryProgram> VulkanDevice::compile_raster(const SourceTree& tree, const std::string& vertex,
                                                           const std::string& fragment, TexelFormat target) const {
  state_->ensure_usable(fragment);
  return std::make_unique<VulkanRasterProgram>(*state_, program_name(*state_, fragment),
                                               stage_spirv(*state_, tree, vertex, {}, nullptr),
                                               stage_spirv(*state_, tree, fragment, {}, nullptr), target, true);
}

std::unique_ptr<QueryProgram> VulkanDevice::compile_full_screen(const SourceTree& tree, const std::string& fragment,
                                                                TexelFormat target,
                                                                const std::vector<Define>& defines) const {
  state_->ensure_usable(fragment);
  return std::make_unique<VulkanRasterProgram>(*state_, program_name(*state_, fragment),
                                               stage_spirv(*state_, tree, kFullScreenVertex, {}, nullptr),
                                               stage_spirv(*state_, tree, fragment, defines, nullptr), target, false);
}

namespace {

const VulkanRasterProgram& raster_program(const QueryProgram& program) {
  const auto* raster = dynamic_cast<const VulkanRasterProgram*>(&program);
  if (raster == nullptr) throw Error("vulkan: a raster program compiled for another device", ExitCode::failed);
  return *raster;
}

template <class Made>
const Made& made_on(const VulkanDevice::State& s, const auto& object, const char* what) {
  const auto* made = dynamic_cast<const Made*>(&object);
  if (made == nullptr || made->owner() != &s)
    throw Error(std::string("vulkan: a ") + what + " made on another device than this one", ExitCode::failed);
  return *made;
}

}  // namespace

std::unique_ptr<DeviceTexture> VulkanDevice::draw_full_screen(const QueryProgram& program, int size,
                                                              const PassResources& resources) const {
  const VulkanRasterProgram& raster = raster_program(program);
  VulkanRasterTarget target(*state_, size, raster.target_format());
  const float nothing[4] = {0, 0, 0, 0};
  clear_raster_target(*state_, target, nothing, {});
  raster.draw(nullptr, {}, target, {}, resources);
  return target.take_colour();
}

std::unique_ptr<DeviceTexture> VulkanDevice::draw_triangles(const QueryProgram& program,
                                                            const std::vector<glm::vec3>& vertices, int size,
                                                            const float clear[4], const PassResources& resources) const {
  const VulkanRasterProgram& raster = raster_program(program);
  VulkanRasterTarget target(*state_, size, raster.target_format());
  clear_raster_target(*state_, target, clear, {});
  const VulkanVertices buffer(*state_, vertices);
  raster.draw(&buffer, {{0, buffer.count()}}, target, {}, resources);
  return target.take_colour();
}

std::unique_ptr<DeviceVertices> VulkanDevice::make_vertices(const std::vector<glm::vec3>& vertices) const {
  state_->ensure_usable("a vertex buffer");
  return std::make_unique<VulkanVertices>(*state_, vertices);
}

void VulkanDevice::write_vertices(const DeviceVertices& to, const std::vector<glm::vec3>& vertices,
                                  std::size_t first, std::size_t count) const {
  const VulkanVertices& buffer = made_on<VulkanVertices>(*state_, to, "vertex buffer");
  if (static_cast<int>(vertices.size()) != buffer.count())
    throw Error("scene geometry: " + std::to_string(vertices.size()) + " vertices, expected " +
                    std::to_string(buffer.count()) + " (the layout it was made with)",
                ExitCode::failed);
  if (first + count > vertices.size()) throw Error("scene geometry: an object past the scene's vertices", ExitCode::failed);
  if (count > 0)
    std::memcpy(static_cast<char*>(buffer.buffer().data()) + first * sizeof(glm::vec3), &vertices[first],
                count * sizeof(glm::vec3));
}

std::unique_ptr<DeviceRasterTarget> VulkanDevice::make_raster_target(int size, TexelFormat format) const {
  state_->ensure_usable("a raster target");
  if (format == TexelFormat::rgba32ui)
    throw Error("vulkan: a raster target of RGBA32UI texels: expected a float format", ExitCode::failed);
  return std::make_unique<VulkanRasterTarget>(*state_, size, format);
}

void VulkanDevice::clear_target(const DeviceRasterTarget& target, const float colour[4],
                                const std::vector<TexelRect>& rects) const {
  clear_raster_target(*state_, made_on<VulkanRasterTarget>(*state_, target, "raster target"), colour, rects);
}

void VulkanDevice::copy_target(const DeviceRasterTarget& source, const DeviceRasterTarget& target,
                               const std::vector<TexelRect>& rects) const {
  const VulkanRasterTarget& from = made_on<VulkanRasterTarget>(*state_, source, "raster target");
  const VulkanRasterTarget& to = made_on<VulkanRasterTarget>(*state_, target, "raster target");
  if (from.size() != to.size() || from.colour().shape().format != to.colour().shape().format)
    throw Error("vulkan: copying between raster targets of different sizes or formats", ExitCode::failed);
  std::vector<VkImageCopy> colour, depth;
  for (const VkRect2D& r : scissor_rects(rects, to.size())) {
    VkImageCopy copy{};
    copy.srcSubresource = copy.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.srcOffset = copy.dstOffset = {r.offset.x, r.offset.y, 0};
    copy.extent = {r.extent.width, r.extent.height, 1};
    colour.push_back(copy);
    copy.srcSubresource.aspectMask = copy.dstSubresource.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
    depth.push_back(copy);
  }
  if (colour.empty()) return;
  state_->submit("copying between raster targets", [&](VkCommandBuffer c) {
    VkMemoryBarrier before{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    before.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                           VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    before.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &before, 0,
                         nullptr, 0, nullptr);
    vkCmdCopyImage(c, from.colour().image(), kImageLayout, to.colour().image(), kImageLayout,
                   static_cast<uint32_t>(colour.size()), colour.data());
    vkCmdCopyImage(c, from.depth().image(), kImageLayout, to.depth().image(), kImageLayout,
                   static_cast<uint32_t>(depth.size()), depth.data());
    VkMemoryBarrier after{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    after.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    after.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                          VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                          VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT;
    vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &after, 0,
                         nullptr, 0, nullptr);
  });
}

void VulkanDevice::draw(const QueryProgram& program, const DeviceVertices& vertices, const std::vector<VertexRun>& runs,
                        const DeviceRasterTarget& target, const std::vector<TexelRect>& rects,
                        const PassResources& resources) const {
  raster_program(program).draw(&made_on<VulkanVertices>(*state_, vertices, "vertex buffer"), runs,
                               made_on<VulkanRasterTarget>(*state_, target, "raster target"), rects, resources);
}

std::unique_ptr<DeviceTexture> VulkanDevice::upload(const Image& image) const {
  state_->ensure_usable("uploading an image");
  return upload_image(*state_, image);
}

std::unique_ptr<QueryBatch> VulkanDevice::make_batch(const std::vector<Image>& inputs, std::size_t results,
                                                     std::size_t word_results) const {
  state_->ensure_usable("a query batch");
  return std::make_unique<VulkanQueryBatch>(*state_, inputs, results, word_results);
}

void VulkanDevice::dispatch(const QueryProgram& program, const QueryBindings& bindings, const QueryBatch& batch,
                            const std::vector<QueryTexture>& textures, const QueryBlock& block) const {
  check_batch_bindings(bindings, batch);
  const auto* vk_batch = dynamic_cast<const VulkanQueryBatch*>(&batch);
  if (vk_batch == nullptr) throw Error("query pass: a batch made on another device than this Vulkan device", ExitCode::failed);
  PassResources resources{textures, {}, {}, block};
  for (std::size_t i = 0; i < bindings.inputs.size(); ++i)
    resources.textures.push_back({bindings.inputs[i], *vk_batch->inputs_[i]});
  for (std::size_t i = 0; i < bindings.results.size(); ++i)
    resources.images.push_back({bindings.results[i], *vk_batch->results_[i]});
  for (std::size_t i = 0; i < bindings.word_results.size(); ++i)
    resources.images.push_back({bindings.word_results[i], *vk_batch->word_results_[i]});
  run(program, resources, vk_batch->width(), vk_batch->height());
}

std::unique_ptr<DeviceTexture> VulkanDevice::make_texture(const TextureShape& shape) const {
  state_->ensure_usable("a texture");
  auto image = std::make_unique<VulkanImage>(*state_, shape);
  image->fill(nullptr, 0);  // into GENERAL layout
  return image;
}

namespace {

const VulkanImage& vulkan_image(const VulkanDevice::State& s, const DeviceTexture& texture) {
  const auto* image = dynamic_cast<const VulkanImage*>(&texture);
  if (image == nullptr || image->owner() != &s)
    throw Error("vulkan: a texture made on another device than this one", ExitCode::failed);
  return *image;
}

}  // namespace

Image VulkanDevice::read_texture(const DeviceTexture& texture, int level, int layer) const {
  const VulkanImage& image = vulkan_image(*state_, texture);
  if (image.integer()) throw Error("vulkan: an RGBA32UI texture read as floats: expected read_words", ExitCode::failed);
  const TextureShape& shape = image.shape();
  return float_image(image.read(level, layer), shape.level_width(level), shape.level_height(level),
                     texel_channels(shape.format));
}

std::vector<std::uint32_t> VulkanDevice::read_words(const DeviceTexture& texture, int level, int layer) const {
  const VulkanImage& image = vulkan_image(*state_, texture);
  if (!image.integer()) throw Error("vulkan: a float texture read as words: expected read_texture", ExitCode::failed);
  return image.read(level, layer);
}

std::unique_ptr<DeviceTexture> VulkanDevice::layer_texture(const DeviceTexture& array, int layer) const {
  const VulkanImage& from = vulkan_image(*state_, array);
  const TextureShape& shape = from.shape();
  if (!shape.array || layer < 0 || layer >= shape.layers)
    throw Error("vulkan: layer " + std::to_string(layer) + " of a texture of " + shape_text(shape) +
                    ": expected an array texture and a layer it has",
                ExitCode::failed);
  auto to = std::make_unique<VulkanImage>(*state_, TextureShape{shape.format, shape.width, shape.height});
  to->fill(nullptr, 0);
  state_->submit("copying a layer", [&](VkCommandBuffer c) {
    image_barrier(c, from.image(), kImageLayout, kImageLayout, VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT,
                  VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkImageCopy copy{};
    copy.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, static_cast<uint32_t>(layer), 1};
    copy.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.extent = {static_cast<uint32_t>(shape.width), static_cast<uint32_t>(shape.height), 1};
    vkCmdCopyImage(c, from.image(), kImageLayout, to->image(), kImageLayout, 1, &copy);
    image_barrier(c, to->image(), kImageLayout, kImageLayout, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  });
  return to;
}

std::unique_ptr<DeviceBuffer> VulkanDevice::make_buffer(std::size_t bytes) const {
  state_->ensure_usable("a storage buffer");
  return std::make_unique<VulkanBuffer>(*state_, bytes);
}

void VulkanDevice::write_buffer(const DeviceBuffer& buffer, std::size_t offset, std::size_t bytes,
                                const void* data) const {
  const auto* vk_buffer = dynamic_cast<const VulkanBuffer*>(&buffer);
  if (vk_buffer == nullptr || vk_buffer->owner() != state_.get())
    throw Error("vulkan: a buffer made on another device than this one", ExitCode::failed);
  if (offset + bytes > vk_buffer->host().size())
    throw Error("vulkan: writing bytes " + std::to_string(offset) + ".." + std::to_string(offset + bytes) +
                    " of a buffer of " + std::to_string(vk_buffer->host().size()),
                ExitCode::failed);
  std::memcpy(static_cast<char*>(vk_buffer->host().data()) + offset, data, bytes);
}

void VulkanDevice::run(const QueryProgram& program, const PassResources& resources, int width, int height) const {
  const auto* vk_program = dynamic_cast<const VulkanQueryProgram*>(&program);
  if (vk_program == nullptr) throw Error("vulkan: a program compiled for another device", ExitCode::failed);
  vk_program->run(resources, width, height, state_->bounds);
}

void VulkanDevice::run_indirect(const QueryProgram& program, const PassResources& resources,
                                const DeviceBuffer& groups) const {
  const auto* vk_program = dynamic_cast<const VulkanQueryProgram*>(&program);
  if (vk_program == nullptr) throw Error("vulkan: a program compiled for another device", ExitCode::failed);
  const auto* vk_groups = dynamic_cast<const VulkanBuffer*>(&groups);
  if (vk_groups == nullptr || vk_groups->owner() != state_.get())
    throw Error("vulkan: a buffer made on another device than this one", ExitCode::failed);
  if (vk_groups->host().size() < 3 * sizeof(std::uint32_t))
    throw Error("vulkan: an indirect dispatch's buffer of " + std::to_string(vk_groups->host().size()) +
                    " bytes: expected at least 12 (the group counts x, y, z)",
                ExitCode::failed);
  vk_program->run(resources, 0, 0, state_->bounds, &vk_groups->host());
}

void VulkanDevice::clear_texture(const DeviceTexture& texture, const float value[4]) const {
  const VulkanImage& image = vulkan_image(*state_, texture);
  const TextureShape& shape = image.shape();
  VkClearColorValue colour{};
  for (int c = 0; c < 4; ++c) {
    colour.float32[c] = value[c];
    if (image.integer()) colour.uint32[c] = static_cast<uint32_t>(value[c]);
  }
  const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, static_cast<uint32_t>(shape.levels), 0,
                                      static_cast<uint32_t>(shape.layers)};
  state_->submit("clearing a texture", [&](VkCommandBuffer c) {
    image_barrier(c, image.image(), kImageLayout, kImageLayout, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                  VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT);
    vkCmdClearColorImage(c, image.image(), kImageLayout, &colour, 1, &range);
    image_barrier(c, image.image(), kImageLayout, kImageLayout, VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
  });
}

bool vulkan_job_abandoned() { return VulkanDevice::State::abandoned_jobs(); }

std::unique_ptr<VulkanDevice> create_vulkan_device(const VulkanSettings& settings) {
  auto s = std::make_unique<VulkanDevice::State>();
  s->settings = settings;
  const auto fail = [](const std::string& why) { return Error("no Vulkan device: " + why, ExitCode::no_context); };

  const bool debug_utils = has_instance_extension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (!settings.validation)
    s->validation_why = "not asked for";
  else if (!has_layer(kValidationLayer))
    s->validation_why = std::string(kValidationLayer) + " is not installed (Debian: vulkan-validationlayers)";
  else if (!debug_utils)
    s->validation_why = "no VK_EXT_debug_utils";
  else
    s->validation_on = true;

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "penumbra";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo instance_info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  instance_info.pApplicationInfo = &app;
  const char* layers[] = {kValidationLayer};
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
  s->waiter = std::make_unique<FenceWaiter>(s->device);
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
