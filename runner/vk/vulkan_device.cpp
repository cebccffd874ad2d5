#include "vk/vulkan_device.h"

#include <vulkan/vulkan.h>

#include <cstring>
#include <utility>

#include "core/error.h"
#include "vk/vulkan_compute.h"
#include "vk/vulkan_raster_program.h"
#include "vk/vulkan_raster_target.h"
#include "vk/vulkan_resources.h"
#include "vk/vulkan_stage_spirv.h"
#include "vk/vulkan_state.h"

// Vulkan's create-info structs are named by their sType and then filled field by field.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace pn {

using namespace vk;  // the executor's parts (vk/vulkan_*.h)

namespace {

std::string version_text(uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
         std::to_string(VK_API_VERSION_PATCH(v));
}

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

const VulkanImage& vulkan_image(const VulkanDevice::State& s, const DeviceTexture& texture) {
  const auto* image = dynamic_cast<const VulkanImage*>(&texture);
  if (image == nullptr || image->owner() != &s)
    throw Error("vulkan: a texture made on another device than this one", ExitCode::failed);
  return *image;
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

}  // namespace pn
