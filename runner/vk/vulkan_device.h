// The Vulkan executor of the query passes (device/query_device.h): `penumbra check --api vulkan`
// runs the checks whose passes are query passes on a Vulkan device — lavapipe here, a GPU's
// driver where one is present — from the vulkan-target SPIR-V that `lint` validates and `bundle
// --target vulkan` writes; `--api hlsl` runs the same passes from their HLSL export (SPIRV-Cross)
// compiled back to SPIR-V by glslang's HLSL front end. Descriptors come from the SPIR-V itself
// (shader/spirv_cross.h): combined samplers for GLSL, texture + sampler pairs for HLSL, storage
// images, std140 uniform blocks. With validation on (the default where the Khronos layer is
// installed) any message of the layer is an error of the dispatch that caused it.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "device/pass_origin.h"
#include "device/query_device.h"
#include "shader/register_plan.h"

namespace pn {

// What the passes are compiled from on the device.
enum class PassLanguage {
  glsl,  // GLSL, the vulkan target (shader/target.h)
  hlsl,  // the HLSL export of that SPIR-V (shader model 5.0), compiled back with glslang
};

struct VulkanSettings {
  PassLanguage language = PassLanguage::glsl;
  bool validation = true;  // the Khronos validation layer, when installed
  // With hlsl: a directory of HLSL exports (X.hlsl, as `bundle X.glsl --target hlsl` writes it)
  // used instead of the generated export of the compute entry X (exports/X.comp or
  // passes/X.comp) compiled without extra defines; checked by usable_hlsl_copies (vk/hlsl_root.h).
  std::optional<std::filesystem::path> hlsl_root;
  // With hlsl: the registers the export is written with (`check --register-shift/--register-space`),
  // bound back at binding register + kHlslSamplerBindingShift for samplers, set = space, as an
  // engine with that plan binds them.
  RegisterPlan registers;
};

class VulkanDevice final : public QueryDevice {
 public:
  ~VulkanDevice() override;
  std::string device_name() const;  // "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string driver() const;       // "llvmpipe, Mesa 22.3.6 …" (driver name and info)
  std::string api_version() const;  // "1.3.230"
  std::string device_type() const;  // "cpu", "integrated GPU", …
  // "on (VK_LAYER_KHRONOS_validation)" or "off (…why)".
  std::string validation() const;
  // Under the bounds every submission is waited for at most bounds.timeout_s (a job past it is
  // abandoned: vk/vulkan_state.h), and the submissions since start_budget() together at most
  // 10 × that (`check` starts a budget for each check).
  void set_dispatch_bounds(const DispatchBounds& bounds);
  void start_budget();

  std::string query_api() const override;
  // With --hlsl-root: where each stage compiled since the last call came from (device/pass_origin.h).
  std::vector<PassOrigin> take_pass_origins() const;
  // The names of the --hlsl-root copies (vk/hlsl_root.h) some compiled stage has read ("pcf.hlsl").
  std::vector<std::string> hlsl_copies_read() const;
  std::unique_ptr<QueryProgram> compile_query(const SourceTree& tree, const std::string& pass,
                                              const std::vector<Define>& defines) const override;
  std::unique_ptr<DeviceTexture> upload(const Image& image) const override;
  std::unique_ptr<QueryBatch> make_batch(const std::vector<Image>& inputs, std::size_t results,
                                         std::size_t word_results) const override;
  void dispatch(const QueryProgram& program, const QueryBindings& bindings, const QueryBatch& batch,
                const std::vector<QueryTexture>& textures, const QueryBlock& block) const override;
  std::unique_ptr<DeviceTexture> make_texture(const TextureShape& shape) const override;
  Image read_texture(const DeviceTexture& texture, int level, int layer) const override;
  std::vector<std::uint32_t> read_words(const DeviceTexture& texture, int level, int layer) const override;
  std::unique_ptr<DeviceTexture> layer_texture(const DeviceTexture& array, int layer) const override;
  std::unique_ptr<DeviceBuffer> make_buffer(std::size_t bytes) const override;
  void write_buffer(const DeviceBuffer& buffer, std::size_t offset, std::size_t bytes, const void* data) const override;
  void run(const QueryProgram& program, const PassResources& resources, int width, int height) const override;
  void run_indirect(const QueryProgram& program, const PassResources& resources,
                    const DeviceBuffer& groups) const override;
  void clear_texture(const DeviceTexture& texture, const float value[4]) const override;
  std::unique_ptr<QueryProgram> compile_raster(const SourceTree& tree, const std::string& vertex,
                                               const std::string& fragment, TexelFormat target) const override;
  std::unique_ptr<QueryProgram> compile_full_screen(const SourceTree& tree, const std::string& fragment,
                                                    TexelFormat target,
                                                    const std::vector<Define>& defines) const override;
  std::unique_ptr<DeviceTexture> draw_full_screen(const QueryProgram& program, int size,
                                                  const PassResources& resources) const override;
  std::unique_ptr<DeviceVertices> make_vertices(const std::vector<glm::vec3>& vertices) const override;
  void write_vertices(const DeviceVertices& to, const std::vector<glm::vec3>& vertices, std::size_t first,
                      std::size_t count) const override;
  std::unique_ptr<DeviceRasterTarget> make_raster_target(int size, TexelFormat format) const override;
  void clear_target(const DeviceRasterTarget& target, const float colour[4],
                    const std::vector<TexelRect>& rects) const override;
  void copy_target(const DeviceRasterTarget& source, const DeviceRasterTarget& target,
                   const std::vector<TexelRect>& rects) const override;
  void draw(const QueryProgram& program, const DeviceVertices& vertices, const std::vector<VertexRun>& runs,
            const DeviceRasterTarget& target, const std::vector<TexelRect>& rects,
            const PassResources& resources) const override;
  std::unique_ptr<DeviceTexture> draw_triangles(const QueryProgram& program, const std::vector<glm::vec3>& vertices,
                                                int size, const float clear[4],
                                                const PassResources& resources) const override;

  struct State;  // vk/vulkan_state.h

 private:
  friend std::unique_ptr<VulkanDevice> create_vulkan_device(const VulkanSettings& settings);
  explicit VulkanDevice(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

// The first device with a compute queue, GPUs before CPUs. Throws Error(ExitCode::no_context)
// naming why there is none (no loader, no driver, no device).
std::unique_ptr<VulkanDevice> create_vulkan_device(const VulkanSettings& settings = {});

// Whether a device was destroyed while a job past its deadline still ran on it (`check
// --gpu-timeout`): a Vulkan job cannot be cancelled, so that device and everything on it were left
// as they were (vk/vulkan_state.h), and the process must end without exit handlers that
// could wait for the job's threads: `penumbra` ends by std::_Exit after its output (cli/main.cpp).
bool vulkan_job_abandoned();

}  // namespace pn
