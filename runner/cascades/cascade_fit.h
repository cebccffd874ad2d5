// Cascaded shadow maps for a directional light (seed 003, issue 14): the
// view frustum split by glsl/cascades.h's hybrid split, and each slice given
// an orthographic light projection. Stable cascades fit the slice's bounding
// sphere (an extent that does not change as the camera turns) and snap its
// centre to the cascade's texel grid (map positions move by whole texels as
// the camera moves); the unstable fit, for comparison, takes the light-space
// bounding square of the slice's corners as it is.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "scene/light_view.h"  // box_corners, directional_light_view

namespace pn {

struct CascadeSettings {
  int count = 3;                  // m, 1 ... PN_CASCADES_MAX
  std::optional<double> lambda;   // the practical scheme's weight in [0, 1]; none: the adaptive lambda
  double enlargement = 1.0;       // k >= 1, the first split's enlargement (1: none)
  double gap = 0.1;               // g, [PN_CASCADE_GAP_MIN, PN_CASCADE_GAP_MAX]
  double band = 0.1;              // the transition band's share of a cascade's depth range, [0, 1)
  bool stable = true;             // sphere fit + texel snap; false: tight corner fit
  int map_size = 1024;            // N >= 4, each cascade's map side

  // Throws Error naming the setting and what was expected.
  void validate() const;
  double effective_lambda(double near, double far) const;
};

// The camera whose view frustum the cascades cover: view matrix, vertical
// field of view, aspect (width / height), near and far view depths.
struct CascadeCamera {
  glm::mat4 view{1.0f};
  double fov_y_radians = 1.0;
  double aspect = 1.0;
  double near_plane = 0.5;
  double far_plane = 400.0;

  void validate() const;
  double tan_diagonal() const;  // sqrt(tan²(fovX/2) + tan²(fovY/2))
  // The four corners of the frustum's cross-section at view depth z, world space.
  std::vector<glm::dvec3> corners_at(double z) const;
};

struct Cascade {
  float split_near = 0, split_far = 0;  // C_i, C_(i+1): the view depths it shades
  float fit_near = 0;                   // the depth its fit starts at: the previous cascade's band start (C_0 for the first)
  float radius = 0;                     // half the side of its square extent, world units
  float texel_size = 0;                 // 2 radius / N (stable: the sphere's diameter over N - 2, a texel's margin each side)
  glm::vec2 centre_light{0.0f};         // the extent's centre in light space (x, y)
  glm::vec2 snapped_texels{0.0f};       // stable: centre_light / texel_size, whole texels
  float depth_near = 0, depth_far = 0;  // the light-space depth range (distances along the light)
  glm::mat4 light_view{1.0f};           // directional_light_view: the same for every cascade and frame
  glm::mat4 light_projection{1.0f};     // orthographic

  // A world point's map position as pnLightProject gives it (texels, continuous) and its
  // linear light depth (distance along the light's direction from the light view's origin), in double.
  glm::dvec3 map_position(const glm::dvec3& world, int map_size) const;
};

// m cascades over the camera's frustum for a light along `light_direction`;
// each cascade's depth range reaches back towards the light to `scene_lo`/`scene_hi`
// (the scene's bounds), so that casters outside the slice still cast.
// Throws Error for bad settings, camera or direction.
std::vector<Cascade> fit_cascades(const CascadeSettings& settings, const CascadeCamera& camera,
                                  const glm::vec3& light_direction, const glm::vec3& scene_lo,
                                  const glm::vec3& scene_hi);

// The split far ends C_1 ... C_m of the settings for a camera (the same floats fit_cascades uses).
std::vector<float> cascade_split_far(const CascadeSettings& settings, double near, double far);

}  // namespace pn
