#include "pass_runners/gbuffer_pass.h"

#include "gl/query_device_gl.h"
#include "gl/std140.h"
#include "pass_runners/scene_draw.h"
#include "scene/light_block.h"

namespace pn::glsl {
#include "passes/gbuffer.h"
PN_STD140_SIZE(PnGBufferParams, 272);
PN_STD140_OFFSET(PnGBufferParams, viewDepthPlane, 256);
PN_STD140_OFFSET(PnGBufferParams, lightView, 64);
PN_STD140_OFFSET(PnGBufferParams, cameraPosition, 192);
PN_STD140_OFFSET(PnGBufferParams, mapSize, 220);
PN_STD140_OFFSET(PnGBufferParams, lightTexelWorld, 228);
PN_STD140_OFFSET(PnGBufferParams, normalOffset, 232);
}  // namespace pn::glsl

namespace pn {

GBufferRenderer::GBufferRenderer(const QueryDevice& device, const SourceTree& tree)
    : device_(&device),
      program_(device.compile_raster(tree, "passes/gbuffer.vert", "passes/gbuffer.frag", TexelFormat::rgba32f)) {}

FloatTexture GBufferRenderer::render(const Scene& scene, int screen_size, float normal_offset_texels,
                                     const MapLight& light, float view_depth_lo, float view_depth_hi) const {
  return take_float_texture(
      render_texture(scene, screen_size, normal_offset_texels, light, view_depth_lo, view_depth_hi));
}

std::unique_ptr<DeviceTexture> GBufferRenderer::render_texture(const Scene& scene, int screen_size,
                                                               float normal_offset_texels, const MapLight& light,
                                                               float view_depth_lo, float view_depth_hi) const {
  glsl::PnGBufferParams block{};
  const glm::mat4 camera_view = scene.camera_view();
  block.cameraViewProjection = glsl::std140_mat4(scene.camera_projection() * camera_view);
  block.lightView = glsl::std140_mat4(light.view);
  block.lightProjection = glsl::std140_mat4(light.projection);
  block.cameraPosition = {scene.camera.eye.x, scene.camera.eye.y, scene.camera.eye.z, 0};
  set_light_fields(block, light.light);
  block.normalOffset = normal_offset_texels;
  // View depth = -(camera view · p).z: minus the view matrix's third row.
  block.viewDepthPlane = {-camera_view[0][2], -camera_view[1][2], -camera_view[2][2], -camera_view[3][2]};
  block.viewDepthLo = view_depth_lo;
  block.viewDepthHi = view_depth_hi;
  const float nothing[4] = {0, 0, 0, 0};
  return device_->draw_triangles(*program_, scene.triangles(), screen_size, nothing, {{}, {}, {}, query_block(block)});
}

}  // namespace pn
