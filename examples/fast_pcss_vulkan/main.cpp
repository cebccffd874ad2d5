// fast_pcss_vulkan_example — Fast PCSS (glsl/fast_pcss.glsl) in a small deferred Vulkan renderer,
// written to be read top to bottom, twice over: once from the GLSL bundle of the module, once from
// its HLSL export (--route glsl | hlsl). It takes from penumbra only what an engine would take,
// files generated at build time by the `penumbra` tool through penumbra_bundle() — no C++ of the
// runner:
//   fast_pcss_bundle.glsl      penumbra_bundle(MODULE fast_pcss.glsl BARE): #included by the GLSL shaders
//   fast_pcss_export.hlsl      penumbra_bundle(MODULE fast_pcss.glsl TARGET hlsl SHADER_MODEL 5.1
//                              REGISTER_SPACE 1): #included by shade.hlsl, its example entry in space 1
//   minmax_mip_build.comp/.hlsl  the library's chain-building pass, as Vulkan GLSL and as HLSL
//   sample_table.inc           `penumbra sample-table`: the 21x8 RG32F sample table's 336 floats
// and the shaders compiled to SPIR-V by glslangValidator at build time (CMakeLists.txt).
//
// Step 0  a Vulkan 1.3 device (lavapipe on the CI machine), the validation layer on when installed
// Step 1  the scene: a model (Assimp) on a ground slab, light and camera (../fast_pcss/scene_setup.h)
// Step 2  the shadow map: linear light depth in an R32F target (shaders/shadow_depth.*)
// Step 3  the aligned min/max mip chain, one dispatch a level: the library's passes/minmax_mip_build.comp
// Step 4  the sample table: a 21x8 RG32F image
// Step 5  the G-buffer: each pixel's receiver (pnLightProject), world position, normal (shaders/gbuffer.*)
// Step 6  the shading pass: pnFastPcss for every pixel (shaders/shade.comp or shade.hlsl)
// Step 7  the lit image and the visibility as PNG
//
//   fast_pcss_vulkan_example [--route glsl|hlsl] [--model PATH] [--out DIR | FILE.png] [--size N] [--bias B]
// Exit status: 0 written; 2 bad command line, model or output path; 1 no Vulkan device, a Vulkan
// failure, or a message of the validation layer.

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "command_line.h"
#include "vulkan_interface.h"
#include "mesh_model.h"
#include "passes/minmax_mip_build.h"  // the library's pass: its bindings and parameter block (GLSL and C++)
#include "png_file.h"
#include "scene_setup.h"
#include "example_spirv.h"  // every shader's SPIR-V, compiled at build time (example::spirv)
#include "vulkan_context.h"

// Vulkan's create-info structs are named by their sType and then filled field by field.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace example {
namespace {

namespace fs = std::filesystem;

enum class Route { glsl, hlsl };

// ---------------------------------------------------------------------------
// Step 1: the light and camera (scene_setup.h, the GL example's numbers) in the frame block
// (vulkan_interface.h). glm's perspective is OpenGL's (depth -1..1), which pnLightProject is given (it
// reads x, y and w); the raster passes take perspectiveZO, Vulkan's depth 0..1, whose x, y and w
// rows are the same. Vulkan's framebuffer row r then holds what OpenGL's row r holds (both put
// NDC y = -1 at row 0), so the pictures, and the pixels that pick the sample table's set, are the
// GL example's.

#define EX_CPP_MAT4(NAME) glm::mat4 NAME;
#define EX_CPP_VEC4(NAME) glm::vec4 NAME;
struct Frame {
  EX_FRAME_MEMBERS(EX_CPP_MAT4, EX_CPP_VEC4)
};
static_assert(sizeof(Frame) == 4 * 64 + 8 * 16, "the frame block: mat4s and vec4s, std140 without padding");

Frame make_frame(float bias) {
  Frame f{};
  f.exLightView = glm::lookAt(kLightPosition, kLightPosition + kLightDirection, kLightMapUp);
  const float fov = static_cast<float>(kLightFovRadians);
  f.exLightProjection = glm::perspective(fov, 1.0f, kLightNear, kLightFar);
  f.exLightRaster = glm::perspectiveZO(fov, 1.0f, kLightNear, kLightFar);
  f.exCameraRaster = glm::perspectiveZO(glm::radians(kCameraFovDegrees), 1.0f, kCameraNear, kCameraFar) *
                     glm::lookAt(kCameraEye, kCameraTarget, glm::vec3(0.0f, 1.0f, 0.0f));
  f.exCameraPosition = glm::vec4(kCameraEye, 1.0f);
  f.exLightPosition = glm::vec4(kLightPosition, 1.0f);
  // PnLight: width, near, nearPlaneWidth (W_n = 2 n tan(fov / 2)), mapSize; spread (0: an area
  // light), texelWorld (0: a perspective map); then the depth bias and the normal offset.
  f.exLight0 = {kLightWidth, kLightNear, static_cast<float>(2.0 * kLightNear * std::tan(0.5 * kLightFovRadians)),
                static_cast<float>(kShadowMapSize)};
  f.exLight1 = {0.0f, 0.0f, bias, kNormalOffsetTexels};
  f.exShading = {kAmbient, 0.0f, 0.0f, 0.0f};
  f.exGroundAlbedo = glm::vec4(kGroundAlbedo, 0.0f);
  f.exModelAlbedo = glm::vec4(kModelAlbedo, 0.0f);
  f.exSky = glm::vec4(kSkyColour, 1.0f);
  return f;
}

// The scene's vertices in one buffer: the ground slab first, then the model.
struct Scene {
  uint32_t ground_vertices = 0, model_vertices = 0;
  std::unique_ptr<Buffer> vertices;
};

Scene upload_scene(const VulkanContext& vk, const std::vector<glm::vec3>& model) {
  std::vector<glm::vec3> vertices = ground_slab_triangles();
  const auto ground = static_cast<uint32_t>(vertices.size());
  vertices.insert(vertices.end(), model.begin(), model.end());
  return {ground, static_cast<uint32_t>(model.size()),
          std::make_unique<Buffer>(vk, vertices.size() * sizeof(glm::vec3), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                   vertices.data())};
}

// One raster pass: `colours` cleared to their values, a D32F depth cleared to 1, `draw` inside.
void raster_pass(VkCommandBuffer c, const Pipeline& pipeline, VkDescriptorSet set,
                 const std::vector<std::pair<const Image*, VkClearColorValue>>& colours, const Image& depth,
                 const std::function<void()>& draw) {
  std::vector<VkRenderingAttachmentInfo> attachments;
  for (const auto& [image, clear] : colours) {
    VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    a.imageView = image->view(), a.imageLayout = VK_IMAGE_LAYOUT_GENERAL;
    a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR, a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    a.clearValue.color = clear;
    attachments.push_back(a);
  }
  VkRenderingAttachmentInfo depth_attachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth_attachment.imageView = depth.view(), depth_attachment.imageLayout = VK_IMAGE_LAYOUT_GENERAL;
  depth_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR, depth_attachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth_attachment.clearValue.depthStencil = {1.0f, 0};
  const VkExtent2D extent{static_cast<uint32_t>(depth.width()), static_cast<uint32_t>(depth.height())};
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, extent}, rendering.layerCount = 1;
  rendering.colorAttachmentCount = static_cast<uint32_t>(attachments.size());
  rendering.pColorAttachments = attachments.data(), rendering.pDepthAttachment = &depth_attachment;
  vkCmdBeginRendering(c, &rendering);
  const VkViewport viewport{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(c, 0, 1, &viewport);
  vkCmdSetScissor(c, 0, 1, &scissor);
  vkCmdBindPipeline(c, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.pipeline());
  vkCmdBindDescriptorSets(c, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout(), 0, 1, &set, 0, nullptr);
  draw();
  vkCmdEndRendering(c);
}

// ---------------------------------------------------------------------------
// Step 2: the shadow map, as LINEAR light depth (what the module compares), cleared to +Inf: no
// occluder. The depth buffer keeps the nearest surface.

std::unique_ptr<Image> render_shadow_map(const VulkanContext& vk, const Scene& scene, const Buffer& frame) {
  const int n = kShadowMapSize;
  auto map = std::make_unique<Image>(vk, VK_FORMAT_R32_SFLOAT, n, n, 1,
                                     VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
  const Image depth(vk, VK_FORMAT_D32_SFLOAT, n, n, 1, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
  Pipeline pipeline(vk, spirv::shadow_depth_vert(), spirv::shadow_depth_frag(),
                    {{EX_FRAME_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}}, 0, {VK_FORMAT_R32_SFLOAT});
  const VkDescriptorSet set = pipeline.bind({{EX_FRAME_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, {}, &frame}});
  VkClearColorValue far{};
  far.float32[0] = std::numeric_limits<float>::infinity();
  vk.submit([&](VkCommandBuffer c) {
    raster_pass(c, pipeline, set, {{map.get(), far}}, depth, [&] {
      const VkDeviceSize offset = 0;
      const VkBuffer vertices = scene.vertices->buffer();
      vkCmdBindVertexBuffers(c, 0, 1, &vertices, &offset);
      vkCmdDraw(c, scene.ground_vertices + scene.model_vertices, 1, 0, 0);
    });
    full_barrier(c);
  });
  return map;
}

// ---------------------------------------------------------------------------
// Step 3: the aligned min/max mip chain with the library's pass, passes/minmax_mip_build.comp
// (its interface: docs/modules/minmax_mip.md, "The pass's interface"): P the least power of two
// >= N (at least 4), an RGBA32F image (P/8) x (P/4) with log2 P - 1 levels (node levels 2 ..
// log2 P), two nodes a texel. One dispatch a level, each reading the level below through the
// sampler. The pass's texel list (binding 4) is read only for an incremental update (texelCount
// > 0), but the SPIR-V uses it statically: a whole-level build binds a buffer there too.
//
// The same pass two ways: its Vulkan GLSL (combined image samplers at bindings 0 and 1), or its
// HLSL export compiled by glslang with --shift-sampler-binding comp 64 (textures t0, t1 at
// bindings 0 and 1, their samplers s0, s1 at 64 and 65) — integration.md, "HLSL compiled to SPIR-V".

std::vector<Binding> mip_build_layout(Route route) {
  const VkDescriptorType texture =
      route == Route::glsl ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
  std::vector<Binding> layout{{PN_MINMAX_MIP_SHADOW_MAP_BINDING, texture},
                              {PN_MINMAX_MIP_READ_BINDING, texture},
                              {PN_MINMAX_MIP_WRITE_BINDING, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                              {PN_MINMAX_MIP_PARAMS_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                              {PN_MINMAX_MIP_TEXELS_BINDING, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  if (route == Route::hlsl)
    for (uint32_t sampler : {64u + PN_MINMAX_MIP_SHADOW_MAP_BINDING, 64u + PN_MINMAX_MIP_READ_BINDING})
      layout.push_back({sampler, VK_DESCRIPTOR_TYPE_SAMPLER});
  return layout;
}

std::unique_ptr<Image> build_mip_chain(const VulkanContext& vk, Route route, const Image& shadow_map) {
  constexpr int kFirstLevel = 2;  // minmax_mip.h's PN_MIP_FIRST_LEVEL
  constexpr int kGroup = 8;       // the pass's local size
  int padded = 1 << kFirstLevel, log2_padded = kFirstLevel;
  while (padded < kShadowMapSize) padded *= 2, ++log2_padded;
  const int levels = log2_padded - kFirstLevel + 1;
  auto chain = std::make_unique<Image>(vk, VK_FORMAT_R32G32B32A32_SFLOAT, std::max((padded >> kFirstLevel) / 2, 1),
                                       padded >> kFirstLevel, levels,
                                       VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT);
  const std::vector<Binding> layout = mip_build_layout(route);
  Pipeline pipeline(vk, route == Route::glsl ? spirv::mip_build_glsl() : spirv::mip_build_hlsl(), "main", layout, 0);
  const Buffer texel_list(vk, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);  // bound, never read (texelCount 0)
  std::vector<std::unique_ptr<Buffer>> params;
  vk.submit([&](VkCommandBuffer c) {
    vkCmdBindPipeline(c, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline());
    for (int level = kFirstLevel; level <= log2_padded; ++level) {
      const PnMipBuildParams block{level, 0, 0};  // texelCount 0: the whole level
      params.push_back(std::make_unique<Buffer>(vk, sizeof block, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, &block));
      std::vector<Binding> resources;
      for (Binding b : layout) {
        switch (b.binding) {
          case PN_MINMAX_MIP_SHADOW_MAP_BINDING: b.view = shadow_map.view(); break;
          case PN_MINMAX_MIP_READ_BINDING: b.view = chain->view(); break;
          case PN_MINMAX_MIP_WRITE_BINDING: b.view = chain->level_view(level - kFirstLevel); break;
          case PN_MINMAX_MIP_PARAMS_BINDING: b.buffer = params.back().get(); break;
          case PN_MINMAX_MIP_TEXELS_BINDING: b.buffer = &texel_list; break;
          default: break;  // the HLSL route's samplers
        }
        resources.push_back(b);
      }
      const VkDescriptorSet set = pipeline.bind(resources);
      vkCmdBindDescriptorSets(c, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout(), 0, 1, &set, 0, nullptr);
      const int rows = padded >> level, columns = std::max(rows / 2, 1);
      vkCmdDispatch(c, static_cast<uint32_t>((columns + kGroup - 1) / kGroup),
                    static_cast<uint32_t>((rows + kGroup - 1) / kGroup), 1);
      full_barrier(c);  // the next level reads this one through the sampler
    }
  });
  return chain;
}

// ---------------------------------------------------------------------------
// Step 4: the sample table as `penumbra sample-table` prints it: 21 columns (the 1-, 4- and
// 16-sample groups) x 8 rows (sets), (x, y) a texel. Made once; it never changes.

constexpr int kSampleTableColumns = 21, kSampleTableSets = 8;
const float kSampleTable[] = {
#include "sample_table.inc"
};
static_assert(sizeof kSampleTable == sizeof(float) * kSampleTableColumns * kSampleTableSets * 2,
              "penumbra sample-table prints 21 x 8 (x, y) pairs");

std::unique_ptr<Image> upload_sample_table(const VulkanContext& vk) {
  auto table = std::make_unique<Image>(vk, VK_FORMAT_R32G32_SFLOAT, kSampleTableColumns, kSampleTableSets, 1,
                                       VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  const Buffer staging(vk, sizeof kSampleTable, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, kSampleTable);
  vk.submit([&](VkCommandBuffer c) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {kSampleTableColumns, kSampleTableSets, 1};
    vkCmdCopyBufferToImage(c, staging.buffer(), table->image(), VK_IMAGE_LAYOUT_GENERAL, 1, &copy);
    full_barrier(c);
  });
  return table;
}

// ---------------------------------------------------------------------------
// Step 5: the G-buffer: per pixel the receiver (u, v, light depth, 1: drawn; cleared to 0: the
// sky), the world position with the albedo's index, and the face normal.

struct GBuffer {
  std::unique_ptr<Image> receivers, world, normal;
};

GBuffer draw_gbuffer(const VulkanContext& vk, const Scene& scene, const Buffer& frame, int size) {
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  const VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
  GBuffer g{std::make_unique<Image>(vk, format, size, size, 1, usage),
            std::make_unique<Image>(vk, format, size, size, 1, usage),
            std::make_unique<Image>(vk, format, size, size, 1, usage)};
  const Image depth(vk, VK_FORMAT_D32_SFLOAT, size, size, 1, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
  Pipeline pipeline(vk, spirv::gbuffer_vert(), spirv::gbuffer_frag(),
                    {{EX_FRAME_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}}, sizeof(int32_t), {format, format, format});
  const VkDescriptorSet set = pipeline.bind({{EX_FRAME_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, {}, &frame}});
  const VkClearColorValue none{};
  vk.submit([&](VkCommandBuffer c) {
    raster_pass(c, pipeline, set, {{g.receivers.get(), none}, {g.world.get(), none}, {g.normal.get(), none}}, depth,
                [&] {
                  const VkDeviceSize offset = 0;
                  const VkBuffer vertices = scene.vertices->buffer();
                  vkCmdBindVertexBuffers(c, 0, 1, &vertices, &offset);
                  const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
                  const int32_t ground = 0, model = 1;
                  vkCmdPushConstants(c, pipeline.layout(), stages, 0, sizeof ground, &ground);
                  vkCmdDraw(c, scene.ground_vertices, 1, 0, 0);
                  vkCmdPushConstants(c, pipeline.layout(), stages, 0, sizeof model, &model);
                  vkCmdDraw(c, scene.model_vertices, 1, scene.ground_vertices, 0);
                });
    full_barrier(c);
  });
  return g;
}

// ---------------------------------------------------------------------------
// Step 6: the shading pass, one invocation a pixel: pnFastPcss, then Lambert x visibility plus
// ambient. The GLSL route binds combined image samplers; the HLSL route textures (tN at binding
// N) and one sampler (s9), the register plan of shade.hlsl (vulkan_interface.h).

struct Shaded {
  FloatImage lit, visibility;
};

FloatImage read_image(const VulkanContext& vk, const Image& image, int channels) {
  const int n = image.width();
  const Buffer readback(vk, static_cast<std::size_t>(n) * n * channels * sizeof(float), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  vk.submit([&](VkCommandBuffer c) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {static_cast<uint32_t>(n), static_cast<uint32_t>(n), 1};
    vkCmdCopyImageToBuffer(c, image.image(), VK_IMAGE_LAYOUT_GENERAL, readback.buffer(), 1, &copy);
    full_barrier(c);
  });
  // Row r of a Vulkan image here is OpenGL's row r (Step 1): FloatImage's rows from the bottom.
  FloatImage out{n, n, channels, std::vector<float>(static_cast<std::size_t>(n) * n * channels)};
  std::memcpy(out.texels.data(), readback.data(), out.texels.size() * sizeof(float));
  return out;
}

Shaded shade(const VulkanContext& vk, Route route, const Buffer& frame, const GBuffer& g, const Image& shadow_map,
             const Image& mip_chain, const Image& sample_table, int size) {
  const Image lit(vk, VK_FORMAT_R32G32B32A32_SFLOAT, size, size, 1,
                  VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  const Image visibility(vk, VK_FORMAT_R32_SFLOAT, size, size, 1,
                         VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  const VkDescriptorType texture =
      route == Route::glsl ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
  std::vector<Binding> resources{{EX_FRAME_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, {}, &frame},
                                 {EX_SHADE_RECEIVERS, texture, g.receivers->view()},
                                 {EX_SHADE_WORLD, texture, g.world->view()},
                                 {EX_SHADE_NORMAL, texture, g.normal->view()},
                                 {EX_SHADE_SHADOW_MAP, texture, shadow_map.view()},
                                 {EX_SHADE_MIP, texture, mip_chain.view()},
                                 {EX_SHADE_SAMPLE_TABLE, texture, sample_table.view()},
                                 {EX_SHADE_VISIBILITY, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, visibility.view()},
                                 {EX_SHADE_LIT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, lit.view()}};
  if (route == Route::hlsl) resources.push_back({EX_SHADE_SAMPLER, VK_DESCRIPTOR_TYPE_SAMPLER});
  Pipeline pipeline(vk, route == Route::glsl ? spirv::shade_glsl() : spirv::shade_hlsl(),
                    route == Route::glsl ? "main" : "shade", resources, 0);
  const VkDescriptorSet set = pipeline.bind(resources);
  vk.submit([&](VkCommandBuffer c) {
    vkCmdBindPipeline(c, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline());
    vkCmdBindDescriptorSets(c, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout(), 0, 1, &set, 0, nullptr);
    const auto groups = static_cast<uint32_t>((size + EX_SHADE_GROUP_SIZE - 1) / EX_SHADE_GROUP_SIZE);
    vkCmdDispatch(c, groups, groups, 1);
    full_barrier(c);
  });
  return {read_image(vk, lit, 4), read_image(vk, visibility, 1)};
}

// ---------------------------------------------------------------------------
// Step 7 and the command line: where the pictures go, and the options.

struct Options : CommonOptions {
  Route route = Route::glsl;
};

Options parse_options(int argc, char** argv) {
  Options o;
  o.out = "fast_pcss_vulkan_out";
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      std::cout << "usage: fast_pcss_vulkan_example [--route glsl|hlsl] [--model PATH] [--out DIR | FILE.png] "
                   "[--size N] [--bias B]\n"
                   "  --route R     glsl: the shaders from the GLSL bundle (default); hlsl: the chain build and the\n"
                   "                shading pass from the HLSL exports\n"
                << common_usage("fast_pcss_vulkan_out");
      std::exit(0);
    }
    if (flag == "--route") {
      if (i + 1 >= argc) throw std::invalid_argument("--route: expected a value");
      const std::string value = argv[++i];
      if (value != "glsl" && value != "hlsl") throw std::invalid_argument("--route '" + value + "': expected glsl or hlsl");
      o.route = value == "glsl" ? Route::glsl : Route::hlsl;
    } else if (!read_common_option(argc, argv, i, o)) {
      throw std::invalid_argument("'" + flag + "': unknown option (--help lists them)");
    }
  }
  check_common_options(o);
  return o;
}

int run(const Options& options) {
  // Bad input is refused before any Vulkan work: the model (Step 1), then the output place.
  const std::vector<glm::vec3> model = load_placed_model(options.model);
  const Outputs outputs = plan_outputs(options);

  // Step 0
  const VulkanContext vk;
  std::cout << "Vulkan: " << vk.device_name() << ", validation "
            << (vk.validation() ? "on (VK_LAYER_KHRONOS_validation)" : "off (the layer is not installed)") << ", route "
            << (options.route == Route::glsl ? "glsl (the GLSL bundle)" : "hlsl (the HLSL exports)") << "\n";
  // Step 1
  const Scene scene = upload_scene(vk, model);
  const Frame frame_values = make_frame(options.bias);
  const Buffer frame(vk, sizeof frame_values, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, &frame_values);
  // Step 2
  const std::unique_ptr<Image> shadow_map = render_shadow_map(vk, scene, frame);
  // Step 3
  const std::unique_ptr<Image> mip_chain = build_mip_chain(vk, options.route, *shadow_map);
  // Step 4
  const std::unique_ptr<Image> sample_table = upload_sample_table(vk);
  // Step 5
  const GBuffer g = draw_gbuffer(vk, scene, frame, options.size);
  // Step 6
  const Shaded shaded = shade(vk, options.route, frame, g, *shadow_map, *mip_chain, *sample_table, options.size);
  if (vk.messages() > 0)
    throw std::runtime_error("the validation layer reported " + std::to_string(vk.messages()) +
                             " message(s), the first: " + vk.first_message());
  // Step 7
  make_directory(outputs.directory);
  write_files({{outputs.lit, encode_png(shaded.lit)}, {outputs.visibility, encode_png(shaded.visibility)}});
  std::cout << "model " << options.model.string() << ": " << model.size() / 3 << " triangles, shadow map "
            << kShadowMapSize << "x" << kShadowMapSize << ", screen " << options.size << "x" << options.size << "\n"
            << "wrote " << outputs.lit.string() << "\nwrote " << outputs.visibility.string() << "\n";
  return 0;
}

}  // namespace
}  // namespace example

int main(int argc, char** argv) {
  try {
    return example::run(example::parse_options(argc, argv));
  } catch (const std::invalid_argument& e) {
    std::cerr << "fast_pcss_vulkan_example: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "fast_pcss_vulkan_example: error: " << e.what() << "\n";
    return 1;
  }
}
