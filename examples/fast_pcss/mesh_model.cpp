#include "mesh_model.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include "scene_setup.h"

namespace example {

std::vector<glm::vec3> load_placed_model(const std::filesystem::path& file) {
  const std::string name = "model '" + file.string() + "'";
  if (!std::filesystem::exists(file)) throw std::invalid_argument(name + ": no such file");
  if (!std::filesystem::is_regular_file(file)) throw std::invalid_argument(name + ": not a regular file");
  if (!std::ifstream(file)) throw std::invalid_argument(name + ": cannot be read");

  // Polygons split into triangles, every node's transform baked into its vertices.
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(
      file.string(), aiProcess_ValidateDataStructure | aiProcess_Triangulate | aiProcess_PreTransformVertices);
  if (scene == nullptr) throw std::invalid_argument(name + ": Assimp cannot read it: " + importer.GetErrorString());
  std::vector<glm::vec3> triangles;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& mesh = *scene->mMeshes[m];
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      if (mesh.mFaces[f].mNumIndices != 3) continue;  // points and lines
      for (unsigned k = 0; k < 3; ++k) {
        const aiVector3D& v = mesh.mVertices[mesh.mFaces[f].mIndices[k]];
        triangles.emplace_back(v.x, v.y, v.z);
      }
    }
  }
  if (triangles.empty()) throw std::invalid_argument(name + ": no triangles");

  // Placement, in double: scale so the longest side is kModelFitSide, then the
  // centre of the footprint at the origin and the lowest point on the ground.
  glm::dvec3 lo(triangles[0]), hi(triangles[0]);
  for (const glm::vec3& v : triangles) lo = glm::min(lo, glm::dvec3(v)), hi = glm::max(hi, glm::dvec3(v));
  const glm::dvec3 extent = hi - lo;
  const double longest = std::max({extent.x, extent.y, extent.z});
  if (!(longest > 0.0)) throw std::invalid_argument(name + ": zero extent");
  const double scale = kModelFitSide / longest;
  const glm::dvec3 base(0.5 * (lo.x + hi.x), lo.y, 0.5 * (lo.z + hi.z));
  for (glm::vec3& v : triangles) v = glm::vec3((glm::dvec3(v) - base) * scale);
  return triangles;
}

std::vector<glm::vec3> ground_slab_triangles() {
  const glm::vec3 lo(-kGroundHalfWidth, -1.0f, -kGroundHalfWidth), hi(kGroundHalfWidth, 0.0f, kGroundHalfWidth);
  const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                          {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
  std::vector<glm::vec3> out;
  for (const auto& f : faces)
    for (int i : {0, 1, 2, 0, 2, 3}) out.push_back(c[f[i]]);
  return out;
}

}  // namespace example
