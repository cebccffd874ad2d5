// A real model as a scene (issue 10): a mesh file read with Assimp, placed on
// the box scenes' ground under their area light (docs/scenes.md, "Model
// scenes"). Every failure — a missing, unreadable, empty, malformed or absurd
// file — is one pn::Error (bad input) that names the file and what was expected.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "scenes.h"

namespace pn {

// The placement rule: scaled uniformly so that the longest side of its
// bounding box is kModelFitSide, centred over the origin in x and z, its
// lowest point at y = 0. The file's axes are kept (+y up, as glTF and OBJ
// define it). So the model lies in [-4, 4] × [0, 8] × [-4, 4]: its top at
// light depth >= 12, behind the near plane (9), where the light's 60° frustum
// is ±6.9 wide, and its shadow (from the light's centre, its top corner lands
// at ±6.7) on the [-10, 10]² ground.
inline constexpr float kModelFitSide = 8.0f;
static_assert(fixtures::kLightHeight - kModelFitSide > fixtures::kLightNear, "a model's top must lie behind the near plane");

// The light width of a model scene, world units (as the boxes scene).
inline constexpr float kModelLightWidth = 3.0f;

// What a model file may be: bounds that refuse absurd input before it costs
// minutes or gigabytes (Assimp reads the whole file into memory).
struct ModelLimits {
  std::uintmax_t max_file_bytes = std::uintmax_t{1} << 30;  // 1 GiB
  std::size_t max_triangles = 2'000'000;                    // 72 MB of vertices, 3 per triangle
  // The import child's (docs/reliability.md, "The import child's limits"): memory beyond what it
  // starts with, and wall-clock time.
  std::uintmax_t max_import_bytes = std::uintmax_t{4} << 30;  // 4 GiB
  int max_import_seconds = 60;
};

// Every triangle of the file in its own coordinates with every node's
// transform applied, 3 vertices each, in the file's winding; polygons are
// triangulated, points and lines dropped. Throws Error for bad input. Assimp
// runs in a child process, so a file that crashes it is bad input too.
std::vector<glm::vec3> load_model_triangles(const std::filesystem::path& file, const ModelLimits& limits = {});

// The placement rule above applied to `triangles` (any coordinates). Throws
// Error naming `file` when the triangles have zero extent or a coordinate that
// is not finite.
std::vector<glm::vec3> place_model_on_ground(const std::vector<glm::vec3>& triangles,
                                             const std::filesystem::path& file);

// The box scenes' ground and light (make_scene) with the file's model placed
// on the ground as Scene::mesh, named after the file's stem. Throws Error for
// bad input, N < 2 or a bad light width.
Scene make_model_scene(const std::filesystem::path& file, int shadow_map_size, float light_width = kModelLightWidth,
                       const ModelLimits& limits = {});

}  // namespace pn
