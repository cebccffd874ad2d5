#include "cascades/cascade_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "cascades/cascade_math.h"
#include "core/error.h"
#include "core/format.h"

namespace pn {
namespace {

Error bad_setting(const std::string& what, double value, const std::string& expected) {
  return Error(what + " " + format_number("%g", value) + ": expected " + expected);
}

}  // namespace

void CascadeSettings::validate() const {
  if (count < 1 || count > PN_CASCADES_MAX)
    throw bad_setting("cascade count", count, "1 ... " + std::to_string(PN_CASCADES_MAX));
  if (lambda && !(*lambda >= 0.0 && *lambda <= 1.0)) throw bad_setting("cascade lambda", *lambda, "0 ... 1");
  if (!(enlargement >= 1.0) || !(enlargement <= std::numeric_limits<float>::max()))  // cascades.h's float k
    throw bad_setting("cascade enlargement k", enlargement, "a finite number >= 1 that float holds (<= 3.4e38)");
  if (!(gap >= PN_CASCADE_GAP_MIN && gap <= PN_CASCADE_GAP_MAX))
    throw bad_setting("cascade gap", gap,
                      format_number("%g", PN_CASCADE_GAP_MIN) + " ... " + format_number("%g", PN_CASCADE_GAP_MAX));
  if (!(band >= 0.0 && band < 1.0)) throw bad_setting("cascade blend band", band, "0 <= band < 1");
  if (map_size < 4) throw bad_setting("cascade map size", map_size, "N >= 4");
}

double CascadeSettings::effective_lambda(double near, double far) const {
  return lambda ? *lambda : cascade_math::pnCascadeAdaptiveLambda(static_cast<float>(near), static_cast<float>(far));
}

void CascadeCamera::validate() const {
  if (!(near_plane > 0) || !std::isfinite(near_plane)) throw bad_setting("camera near", near_plane, "a finite number > 0");
  if (!(far_plane > near_plane) || !std::isfinite(far_plane)) throw bad_setting("camera far", far_plane, "a finite number > near");
  if (!(fov_y_radians > 0 && fov_y_radians < 3.14159265358979))
    throw bad_setting("camera field of view", fov_y_radians, "0 < fov < pi radians");
  if (!(aspect > 0) || !std::isfinite(aspect)) throw bad_setting("camera aspect", aspect, "a finite number > 0");
}

double CascadeCamera::tan_diagonal() const {
  const double ty = std::tan(0.5 * fov_y_radians), tx = ty * aspect;
  return std::sqrt(tx * tx + ty * ty);
}

std::vector<glm::dvec3> CascadeCamera::corners_at(double z) const {
  const glm::dmat4 to_world = glm::inverse(glm::dmat4(view));
  const double ty = std::tan(0.5 * fov_y_radians) * z, tx = ty * aspect;
  std::vector<glm::dvec3> out;
  for (const auto& [sx, sy] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
    out.push_back(glm::dvec3(to_world * glm::dvec4(sx * tx, sy * ty, -z, 1.0)));
  return out;
}

glm::dvec3 Cascade::map_position(const glm::dvec3& world, int map_size) const {
  const glm::dvec4 view = glm::dmat4(light_view) * glm::dvec4(world, 1.0);
  const glm::dvec4 clip = glm::dmat4(light_projection) * view;
  return {(clip.x / clip.w * 0.5 + 0.5) * map_size, (clip.y / clip.w * 0.5 + 0.5) * map_size, -view.z};
}

std::vector<float> cascade_split_far(const CascadeSettings& settings, double near, double far) {
  const float lambda = static_cast<float>(settings.effective_lambda(near, far));
  std::vector<float> out;
  for (int i = 1; i <= settings.count; ++i)
    out.push_back(cascade_math::pnCascadeHybridSplit(lambda, static_cast<float>(near), static_cast<float>(far), i,
                                                     settings.count, static_cast<float>(settings.enlargement),
                                                     static_cast<float>(settings.gap)));
  return out;
}

std::vector<Cascade> fit_cascades(const CascadeSettings& settings, const CascadeCamera& camera,
                                  const glm::vec3& light_direction, const glm::vec3& scene_lo,
                                  const glm::vec3& scene_hi) {
  settings.validate();
  camera.validate();
  const glm::mat4 light_view = directional_light_view(light_direction, scene_lo, scene_hi);
  const glm::dmat4 to_light(light_view);
  double scene_depth_lo = INFINITY;  // where every cascade's depth range starts: casters outside its slice still cast
  for (const glm::dvec3& c : box_corners(scene_lo, scene_hi))
    scene_depth_lo = std::min(scene_depth_lo, -(to_light * glm::dvec4(c, 1.0)).z);
  const std::vector<float> split_far = cascade_split_far(settings, camera.near_plane, camera.far_plane);
  const glm::dmat4 to_world = glm::inverse(glm::dmat4(camera.view));
  const float tan_diagonal = static_cast<float>(camera.tan_diagonal());
  std::vector<Cascade> out;
  for (int i = 0; i < settings.count; ++i) {
    Cascade c;
    c.light_view = light_view;
    c.split_near = i == 0 ? static_cast<float>(camera.near_plane) : split_far[static_cast<size_t>(i - 1)];
    c.split_far = split_far[static_cast<size_t>(i)];
    const float previous_start = i <= 1 ? static_cast<float>(camera.near_plane) : split_far[static_cast<size_t>(i - 2)];
    c.fit_near = i == 0 ? c.split_near
                        : c.split_near - static_cast<float>(settings.band) * (c.split_near - previous_start);
    double depth_hi = -INFINITY;
    if (settings.stable) {
      const glm::vec2 sphere = cascade_math::pnCascadeSliceSphere(c.fit_near, c.split_far, tan_diagonal);
      const glm::dvec3 centre_world(to_world * glm::dvec4(0.0, 0.0, -static_cast<double>(sphere.x), 1.0));
      const glm::dvec4 centre = to_light * glm::dvec4(centre_world, 1.0);
      // N texels span the sphere and a texel's margin each side, so that the snap (which
      // moves the centre by up to half a texel) never leaves a slice's corner outside.
      c.texel_size = 2.0f * sphere.y / static_cast<float>(settings.map_size - 2);
      c.radius = 0.5f * c.texel_size * static_cast<float>(settings.map_size);
      c.snapped_texels = cascade_math::pnCascadeSnapTexels(glm::vec2(centre.x, centre.y), c.texel_size);
      c.centre_light = c.snapped_texels * c.texel_size;
      depth_hi = -centre.z + c.radius;
    } else {
      glm::dvec2 lo(INFINITY), hi(-INFINITY);
      for (double z : {static_cast<double>(c.fit_near), static_cast<double>(c.split_far)})
        for (const glm::dvec3& corner : camera.corners_at(z)) {
          const glm::dvec4 p = to_light * glm::dvec4(corner, 1.0);
          lo = glm::min(lo, glm::dvec2(p)), hi = glm::max(hi, glm::dvec2(p));
          depth_hi = std::max(depth_hi, -p.z);
        }
      c.radius = static_cast<float>(0.5 * std::max(hi.x - lo.x, hi.y - lo.y));
      c.texel_size = 2.0f * c.radius / static_cast<float>(settings.map_size);
      c.centre_light = glm::vec2(0.5 * (lo + hi));
    }
    c.depth_near = static_cast<float>(scene_depth_lo);
    c.depth_far = static_cast<float>(std::max(depth_hi, scene_depth_lo + 1.0));
    c.light_projection = glm::ortho(c.centre_light.x - c.radius, c.centre_light.x + c.radius,
                                    c.centre_light.y - c.radius, c.centre_light.y + c.radius, c.depth_near, c.depth_far);
    out.push_back(c);
  }
  return out;
}

}  // namespace pn
