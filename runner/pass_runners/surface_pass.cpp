#include "pass_runners/surface_pass.h"

#include <string>

#include "core/error.h"
#include "gl/query_device_gl.h"
#include "gl/std140.h"

namespace pn::glsl {
#include "passes/surface.h"
PN_STD140_SIZE(PnSurfaceParams, 160);
PN_STD140_OFFSET(PnSurfaceParams, cameraPosition, 64);
PN_STD140_OFFSET(PnSurfaceParams, boxAlbedo, 144);
}  // namespace pn::glsl

namespace pn {

SurfaceRenderer::SurfaceRenderer(const QueryDevice& device, const SourceTree& tree)
    : device_(&device),
      program_(device.compile_raster(tree, "passes/surface.vert", "passes/surface.frag", TexelFormat::rgba32f)) {}

FloatTexture SurfaceRenderer::render(const Scene& scene, int screen_size) const {
  return take_float_texture(render_texture(scene, screen_size));
}

std::unique_ptr<DeviceTexture> SurfaceRenderer::render_texture(const Scene& scene, int screen_size) const {
  if (screen_size < 1) throw Error("screen size " + std::to_string(screen_size) + ": expected at least 1");
  if (scene.boxes.empty()) throw Error("scene '" + scene.name + "': expected a ground box (boxes[0])");
  const auto point = [](const glm::vec3& v) { return glsl::std140_vec4(glm::vec4(v, 0.0f)); };
  glsl::PnSurfaceParams block{};
  block.cameraViewProjection = glsl::std140_mat4(scene.camera_projection() * scene.camera_view());
  block.cameraPosition = point(glm::vec3(glm::inverse(scene.camera_view())[3]));
  block.lightPosition = scene.sun ? glsl::std140_vec4(glm::vec4(-glm::normalize(scene.sun->direction), 0.0f))
                                  : glsl::std140_vec4(glm::vec4(scene.light_position, 1.0f));
  block.groundLo = point(scene.boxes[0].lo);
  block.groundHi = point(scene.boxes[0].hi);
  block.groundAlbedo = point(kGroundAlbedo);
  block.boxAlbedo = point(kBoxAlbedo);
  const float nothing[4] = {0, 0, 0, 0};
  return device_->draw_triangles(*program_, scene.triangles(), screen_size, nothing, {{}, {}, {}, query_block(block)});
}

}  // namespace pn
