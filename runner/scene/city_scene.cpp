#include "scene/city_scene.h"

#include <cmath>

#include "core/error.h"
#include "core/named.h"
#include "core/seeded_random.h"
#include "scene/model.h"

namespace pn {
namespace {

constexpr double kPi = 3.14159265358979;
double radians(double degrees) { return degrees * kPi / 180.0; }

void add_buildings(const fixtures::CitySceneFixture& f, Scene& scene) {
  using namespace fixtures;
  SeededRandom random(f.seed);
  const int blocks = static_cast<int>(std::floor(2.0f * f.half_width / f.block_pitch));
  const float first = -0.5f * static_cast<float>(blocks) * f.block_pitch;  // a street centre line
  const float block = f.block_pitch - f.street_width;
  const auto height = [&] {
    const float u = random.uniform_float(0.0f, 1.0f);
    return kCityMinHeight + (kCityMaxHeight - kCityMinHeight) * u * u * u;
  };
  for (int i = 0; i < blocks; ++i)
    for (int j = 0; j < blocks; ++j) {
      const float x0 = first + static_cast<float>(i) * f.block_pitch + 0.5f * f.street_width;
      const float z0 = first + static_cast<float>(j) * f.block_pitch + 0.5f * f.street_width;
      if (random.uniform_float(0.0f, 1.0f) < kCityWholeBlock) {
        const float inset = random.uniform_float(0.0f, 2.0f);
        scene.boxes.push_back({{x0 + inset, 0.0f, z0 + inset}, {x0 + block - inset, height(), z0 + block - inset}});
        continue;
      }
      const float lot = 0.5f * block;
      for (int lx = 0; lx < 2; ++lx)
        for (int lz = 0; lz < 2; ++lz) {
          if (random.uniform_float(0.0f, 1.0f) >= kCityLotBuilt) continue;
          const float inset = random.uniform_float(0.5f, 2.0f);
          const float x = x0 + static_cast<float>(lx) * lot, z = z0 + static_cast<float>(lz) * lot;
          scene.boxes.push_back({{x + inset, 0.0f, z + inset}, {x + lot - inset, height(), z + lot - inset}});
        }
    }
}

void add_street_furniture(const fixtures::CitySceneFixture& f, Scene& scene) {
  using namespace fixtures;
  const float h = 0.5f * kCityPoleSide;
  for (float z = -f.half_width + kCityPoleStep; z < f.half_width; z += kCityPoleStep)
    for (float x : {-kCityPoleOffset, kCityPoleOffset})
      scene.boxes.push_back({{x - h, 0.0f, z - h}, {x + h, kCityPoleHeight, z + h}});
}

void add_models(Scene& scene) {
  using namespace fixtures;
  std::vector<glm::vec3> placed[2];
  for (int m = 0; m < 2; ++m) placed[m] = place_model_on_ground(load_model_triangles(kCityModels[m]), kCityModels[m]);
  const float scale = kCityModelSide / kModelFitSide;
  for (int k = 0; k < kCityModelCount; ++k) {
    const float turn = static_cast<float>(radians(40.0 * k)), c = std::cos(turn), s = std::sin(turn);
    const glm::vec3 at(k % 2 == 0 ? -kCityModelOffset : kCityModelOffset, 0.0f,
                       kCityModelFirstZ - kCityModelStep * static_cast<float>(k));
    for (const glm::vec3& v : placed[k % 2])
      scene.mesh.push_back(at + scale * glm::vec3(c * v.x + s * v.z, v.y, -s * v.x + c * v.z));
  }
}

}  // namespace

const fixtures::CitySceneFixture* find_city_scene_fixture_or_null(const std::string& name) {
  return find_named_or_null(fixtures::kCityScenes, name);
}

SceneCamera city_camera(int frame) {
  using namespace fixtures;
  const double k = frame;
  const double yaw = radians(kCityCameraYawDegrees + kCityCameraTurnDegrees * k), pitch = radians(kCityCameraPitchDegrees);
  SceneCamera camera;
  camera.eye = glm::vec3(0.0f, kCityCameraHeight, static_cast<float>(kCityCameraStartZ - kCityCameraStep * k));
  camera.target = camera.eye + glm::vec3(glm::dvec3(std::cos(pitch) * std::sin(yaw), -std::sin(pitch),
                                                    -std::cos(pitch) * std::cos(yaw)));
  camera.fov_degrees = kCityCameraFovDegrees;
  camera.near_plane = kCityCameraNear;
  camera.far_plane = kCityCameraFar;
  return camera;
}

Scene make_city_scene(const fixtures::CitySceneFixture& fixture, int shadow_map_size) {
  Scene scene;
  scene.name = fixture.name;
  scene.light.map_size = shadow_map_size;
  if (shadow_map_size < 2) throw Error("shadow map size " + std::to_string(shadow_map_size) + ": expected N >= 2");
  const float g = fixture.half_width;
  scene.boxes.push_back({{-g, -1.0f, -g}, {g, 0.0f, g}});
  add_buildings(fixture, scene);
  add_street_furniture(fixture, scene);
  add_models(scene);
  scene.camera = city_camera(0);
  const double elevation = radians(fixture.sun_elevation_degrees), azimuth = radians(fixture.sun_azimuth_degrees);
  // The direction the light travels: down, and away from the sun's azimuth.
  const glm::dvec3 towards_sun(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                               -std::cos(elevation) * std::cos(azimuth));
  light_by_sun(scene, glm::vec3(-towards_sun), radians(fixture.sun_diameter_degrees));
  return scene;
}

}  // namespace pn
