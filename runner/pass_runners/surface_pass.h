// Runner side of glsl/passes/surface.vert/.frag: what a lit image needs besides
// visibility — per pixel the albedo of the surface seen and the cosine of the
// light's centre on its face (metrics/lit_image.h composes them).
#pragma once

#include <memory>

#include <glm/glm.hpp>

#include "device/query_device.h"
#include "gl/texture.h"
#include "scene/scene.h"
#include "shader/source_tree.h"

namespace pn {

// Constant albedos (linear RGB): boxes[0], the ground, and every other box.
inline constexpr glm::vec3 kGroundAlbedo{0.80f, 0.80f, 0.78f};  // light grey
inline constexpr glm::vec3 kBoxAlbedo{0.85f, 0.55f, 0.30f};     // warm orange-brown

class SurfaceRenderer {
 public:
  SurfaceRenderer(const QueryDevice& device, const SourceTree& tree);

  // RGBA32F screen_size x screen_size, rows from the bottom like GBufferRenderer: rgb the albedo,
  // a = max(dot(N, L), 0) with N the face normal turned toward the camera and L the unit direction
  // to the light's centre; (0, 0, 0, 0) where the pixel sees no surface. Throws Error for screen_size < 1.
  FloatTexture render(const Scene& scene, int screen_size) const;
  // The same on any executor, as a texture on the device (render: a GL texture).
  std::unique_ptr<DeviceTexture> render_texture(const Scene& scene, int screen_size) const;

 private:
  const QueryDevice* device_;
  std::unique_ptr<QueryProgram> program_;
};

}  // namespace pn
