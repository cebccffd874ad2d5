// Step 1: the model's triangles from a mesh file (Assimp), placed on the
// ground (scene_setup.h: longest side kModelFitSide, centred, standing on y = 0).
#pragma once

#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

namespace example {

// Three vertices a triangle, world space. Throws std::invalid_argument naming
// the file for a missing or unreadable file, or one without triangles.
std::vector<glm::vec3> load_placed_model(const std::filesystem::path& file);

// The ground slab's 12 triangles (its top face at y = 0).
std::vector<glm::vec3> ground_slab_triangles();

}  // namespace example
