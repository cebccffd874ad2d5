// The cascades check's fit cases (CPU, the runner's cascades/cascade_fit):
// map positions along a camera path move by whole texels under the stable fit
// and slide under the tight one, and every fitted slice lies inside its map.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "cascades/cascade_fit.h"
#include "check/cascades_cases.h"
#include "core/format.h"

namespace pn {

// --- the runner's fit: stability along a camera path, coverage -------------------------------------------

namespace {

struct PathMeasure {
  double largest_fraction = 0;  // the largest |Δu − round(Δu)| over points, frames and cascades (texels)
  double radius_change = 0;     // the largest |r_f − r_0| (world units)
  int uncovered = 0;            // fitted-slice corners outside their cascade's map or depth range
};

PathMeasure walk_camera_path(bool stable, int count) {
  CascadeSettings settings;
  settings.count = count, settings.stable = stable, settings.map_size = 1024;
  const glm::vec3 light(-0.35f, -0.8f, -0.45f), scene_lo(-200.0f, -1.0f, -200.0f), scene_hi(200.0f, 60.0f, 200.0f);
  std::mt19937 random(0xcafe + static_cast<unsigned>(count));
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<glm::dvec3> points;
  for (int p = 0; p < 64; ++p) points.push_back({150 * unit(random), 20 + 20 * unit(random), 150 * unit(random)});
  PathMeasure measure;
  std::vector<Cascade> first;
  std::vector<std::vector<glm::dvec3>> first_positions;
  const glm::dvec3 start(10.0, 1.7, 20.0);
  for (int frame = 0; frame < 40; ++frame) {
    // Sub-texel moves of the finest cascade (its texel is ~2 cm here) and turns of up to half a degree.
    const double step = frame == 0 ? 0.0 : 0.01;
    const glm::dvec3 eye = start + step * glm::dvec3(unit(random), 0.2 * unit(random), unit(random));
    const double yaw = 0.6 + (frame == 0 ? 0.0 : 0.0087 * unit(random)), pitch = -0.15;
    const glm::dvec3 forward(std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw));
    CascadeCamera camera;
    camera.view = glm::mat4(glm::lookAt(eye, eye + forward, glm::dvec3(0, 1, 0)));
    camera.fov_y_radians = 1.0, camera.aspect = 16.0 / 9.0, camera.near_plane = 0.5, camera.far_plane = 400.0;
    const std::vector<Cascade> cascades = fit_cascades(settings, camera, light, scene_lo, scene_hi);
    for (size_t c = 0; c < cascades.size(); ++c) {
      std::vector<glm::dvec3> positions;
      for (const glm::dvec3& p : points) positions.push_back(cascades[c].map_position(p, settings.map_size));
      if (frame == 0) {
        first_positions.push_back(positions);
      } else {
        for (size_t p = 0; p < points.size(); ++p)
          for (int axis = 0; axis < 2; ++axis) {
            const double moved = positions[p][axis] - first_positions[c][p][axis];
            measure.largest_fraction = std::max(measure.largest_fraction, std::fabs(moved - std::round(moved)));
          }
        measure.radius_change = std::max(measure.radius_change, std::fabs(double(cascades[c].radius) - first[c].radius));
      }
      for (double z : {double(cascades[c].fit_near), double(cascades[c].split_far)})
        for (const glm::dvec3& corner : camera.corners_at(z)) {
          const glm::dvec3 m = cascades[c].map_position(corner, settings.map_size);
          // Within float rounding of the map's edges (the tight fit puts corners on them); the depth
          // range starts at the scene's nearest point, so only its far end is the fit's to meet.
          const double margin = 1e-3, n = settings.map_size;
          const bool inside = m.x >= -margin && m.x <= n + margin && m.y >= -margin && m.y <= n + margin &&
                              m.z <= cascades[c].depth_far * (1 + 1e-6);
          measure.uncovered += inside ? 0 : 1;
        }
    }
    if (frame == 0) first = cascades;
  }
  return measure;
}

}  // namespace

void stability_cases(std::vector<CaseResult>& results) {
  for (int count : {1, 3, 4}) {
    const PathMeasure stable = walk_camera_path(true, count), unstable = walk_camera_path(false, count);
    const std::string name = "camera path (40 frames, moves < 1 texel, turns < 0.5 deg), m " + std::to_string(count);
    results.push_back(row_case(name + ", stable: map positions move by whole texels (largest fraction " +
                                   format_number("%.2g", stable.largest_fraction) + ")",
                               {0.0f}, {static_cast<float>(stable.largest_fraction)}, Tolerance::absolute(0.01)));
    results.push_back(row_case(name + ", stable: radius unchanged", {0.0f}, {static_cast<float>(stable.radius_change)},
                               Tolerance::exact()));
    // The contrast: the tight fit's positions slide by fractions of a texel; the case holds
    // when the measure sees at least 0.05 texel (observed = min(fraction, 0.05)).
    results.push_back(row_case(name + ", unstable fit: positions slide (largest fraction " +
                                   format_number("%.2g", unstable.largest_fraction) + " >= 0.05)",
                               {0.05f}, {static_cast<float>(std::min(unstable.largest_fraction, 0.05))},
                               Tolerance::exact()));
    results.push_back(row_case(name + ": every fitted slice's corner inside its cascade's map and before its depth range's end (both fits)",
                               {0.0f, 0.0f}, {static_cast<float>(stable.uncovered), static_cast<float>(unstable.uncovered)},
                               Tolerance::exact()));
  }
}

}  // namespace pn
