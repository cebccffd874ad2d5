// Model scenes: the triangles of real files, counted independently of Assimp;
// the placement rule checked from the placed vertices and the light's own
// matrices; every bad input as one line that names the file.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unistd.h>

#include "core/error.h"
#include "scene/model.h"
#include "temp_tree.h"

using pn::test::TempTree;
namespace fs = std::filesystem;

namespace {

const fs::path kModels = "/usr/share/assimp/models";  // Debian's assimp-testmodels
const fs::path kEngine = kModels / "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
const fs::path kSpider = kModels / "OBJ/spider.obj";

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Triangles of a binary glTF read from its JSON chunk alone: every node of the
// default scene, recursively, once per instance; triangle-list primitives
// (mode 4, the default) count indices / 3, or positions / 3 when unindexed.
std::size_t glb_triangle_count(const fs::path& file) {
  const std::string glb = bytes_of(file);
  REQUIRE(glb.size() > 20);
  REQUIRE(glb.compare(0, 4, "glTF") == 0);
  std::uint32_t json_length = 0;
  std::memcpy(&json_length, glb.data() + 12, 4);
  const nlohmann::json gltf = nlohmann::json::parse(glb.substr(20, json_length));
  std::size_t count = 0;
  std::vector<int> nodes = gltf["scenes"][gltf.value("scene", 0)]["nodes"].get<std::vector<int>>();
  while (!nodes.empty()) {
    const nlohmann::json& node = gltf["nodes"][nodes.back()];
    nodes.pop_back();
    for (int child : node.value("children", std::vector<int>{})) nodes.push_back(child);
    if (!node.contains("mesh")) continue;
    for (const auto& primitive : gltf["meshes"][node["mesh"].get<int>()]["primitives"]) {
      REQUIRE(primitive.value("mode", 4) == 4);
      const int accessor = primitive.contains("indices") ? primitive["indices"].get<int>()
                                                         : primitive["attributes"]["POSITION"].get<int>();
      count += gltf["accessors"][accessor]["count"].get<std::size_t>() / 3;
    }
  }
  return count;
}

// Triangles of an OBJ by hand: a face of n vertices is n − 2 triangles; p and l lines are none.
std::size_t obj_triangle_count(const fs::path& file) {
  std::istringstream text(bytes_of(file));
  std::size_t count = 0;
  for (std::string line; std::getline(text, line);) {
    std::istringstream words(line);
    std::string word;
    if (!(words >> word) || word != "f") continue;
    std::size_t vertices = 0;
    while (words >> word) ++vertices;
    count += vertices - 2;
  }
  return count;
}

struct Bounds {
  glm::vec3 lo{INFINITY}, hi{-INFINITY};
};
Bounds bounds_of(const std::vector<glm::vec3>& vertices) {
  Bounds b;
  for (const glm::vec3& v : vertices) b.lo = glm::min(b.lo, v), b.hi = glm::max(b.hi, v);
  return b;
}

// The documented placement, from the placed vertices and the scene's own light.
void check_placement(const pn::Scene& scene) {
  const Bounds b = bounds_of(scene.mesh);
  const glm::vec3 extent = b.hi - b.lo;
  CHECK(b.lo.y == Approx(0.0).margin(1e-6));  // standing on the ground
  CHECK(0.5f * (b.lo.x + b.hi.x) == Approx(0.0).margin(1e-5));
  CHECK(0.5f * (b.lo.z + b.hi.z) == Approx(0.0).margin(1e-5));
  CHECK(std::max({extent.x, extent.y, extent.z}) == Approx(pn::kModelFitSide).epsilon(1e-6));
  const double ground = pn::fixtures::kGroundHalfWidth, n = scene.light.map_size;
  int outside = 0;
  for (const glm::vec3& v : scene.mesh) {
    const pn::Receiver r = pn::project_to_light(scene, glm::dvec3(v));
    const bool in_frustum = r.valid && r.u >= 0 && r.u <= n && r.v >= 0 && r.v <= n &&
                            r.depth > scene.light.near_plane && r.depth < scene.light.far_plane;
    // Its shadow from the light's centre falls on the ground.
    const double to_ground = scene.light_position.y / (scene.light_position.y - v.y);
    const bool shadow_on_ground = std::fabs(v.x * to_ground) <= ground && std::fabs(v.z * to_ground) <= ground;
    outside += !in_frustum || !shadow_on_ground;
  }
  CHECK(outside == 0);
}

std::string error_of(const fs::path& file, const pn::ModelLimits& limits = {}) {
  try {
    pn::make_model_scene(file, 64, pn::kModelLightWidth, limits);
  } catch (const pn::Error& e) {
    CHECK(e.code() == pn::ExitCode::bad_input);
    const std::string message = e.what();
    CHECK(message.find('\n') == std::string::npos);
    CHECK(message.find('\r') == std::string::npos);
    return message;
  }
  return "no error";
}

std::string quoted(const fs::path& file) { return "model '" + file.string() + "': "; }

const char* const kCubeObj =
    "# a unit cube of quads, plus a line and a point that are not triangles\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n"
    "l 1 7\np 3\n";

}  // namespace

TEST_CASE("model scenes: the glTF engine has every triangle of every node instance, counted from its JSON") {
  const pn::Scene scene = pn::make_model_scene(kEngine, 256);
  const std::size_t expected = glb_triangle_count(kEngine);
  CHECK(expected == 121496);  // 75 730 distinct, some meshes drawn by several nodes
  CHECK(scene.mesh.size() == 3 * expected);
  CHECK(scene.name == "2CylinderEngine");
  check_placement(scene);
}

TEST_CASE("model scenes: the spider OBJ has as many triangles as its f lines, counted by hand") {
  const pn::Scene scene = pn::make_model_scene(kSpider, 256);
  const std::size_t expected = obj_triangle_count(kSpider);
  CHECK(expected == 1368);
  CHECK(scene.mesh.size() == 3 * expected);
  CHECK(scene.name == "spider");
  check_placement(scene);
}

TEST_CASE("model scenes: the box scenes' ground and light, the mesh after the ground's 36 vertices in triangles()") {
  TempTree dir(TempTree::Files{{"cube.obj", kCubeObj}});
  const pn::Scene scene = pn::make_model_scene(dir.root() / "cube.obj", 128, 2.5f);
  const pn::Scene boxes = pn::make_scene(pn::find_scene_fixture("boxes"), 128);
  REQUIRE(scene.boxes.size() == 1);
  CHECK(scene.boxes[0].lo == boxes.boxes[0].lo);
  CHECK(scene.boxes[0].hi == boxes.boxes[0].hi);
  CHECK(scene.light_position == boxes.light_position);
  CHECK(scene.light.near_plane == boxes.light.near_plane);
  CHECK(scene.light.far_plane == boxes.light.far_plane);
  CHECK(scene.light.fov_radians == boxes.light.fov_radians);
  CHECK(scene.light.map_size == 128);
  CHECK(scene.light.width == 2.5);
  const std::vector<glm::vec3> all = scene.triangles();
  REQUIRE(all.size() == 36 + scene.mesh.size());
  CHECK(std::equal(scene.mesh.begin(), scene.mesh.end(), all.begin() + 36));
  CHECK_THROWS_WITH(pn::make_model_scene(dir.root() / "cube.obj", 1), Catch::Contains("shadow map size 1"));
  CHECK_THROWS_WITH(pn::make_model_scene(dir.root() / "cube.obj", 64, -1.0f), Catch::Contains("light width -1"));
}

TEST_CASE("model scenes: a unit cube of quads is 12 triangles filling [-4, 4] x [0, 8] x [-4, 4] exactly") {
  TempTree dir(TempTree::Files{{"cube.obj", kCubeObj}});
  const pn::Scene scene = pn::make_model_scene(dir.root() / "cube.obj", 64);
  CHECK(scene.name == "cube");
  REQUIRE(scene.mesh.size() == 3 * 12);  // 6 quads; the line and the point dropped
  for (const glm::vec3& v : scene.mesh) {
    INFO(v.x << " " << v.y << " " << v.z);
    CHECK((v.x == -4.0f || v.x == 4.0f));
    CHECK((v.y == 0.0f || v.y == 8.0f));
    CHECK((v.z == -4.0f || v.z == 4.0f));
  }
}

TEST_CASE("model scenes: one triangle, y up, scaled by 8 / its longest side, footprint centred, lowest point at 0") {
  // Extents 2 (x), 4 (y), 2 (z): scale 2; footprint centre (2, 4); lowest y 2.
  TempTree dir(TempTree::Files{{"one.obj", "v 1 2 3\nv 3 2 3\nv 1 6 5\nf 1 2 3\n"}});
  const std::vector<glm::vec3> mesh = pn::make_model_scene(dir.root() / "one.obj", 64).mesh;
  REQUIRE(mesh.size() == 3);
  CHECK(mesh[0] == glm::vec3(-2, 0, -2));
  CHECK(mesh[1] == glm::vec3(2, 0, -2));
  CHECK(mesh[2] == glm::vec3(-2, 8, 2));
}

TEST_CASE("model scenes: nested node transforms are applied (an instanced glTF node moved by its parent)") {
  // One triangle mesh drawn by two nodes: as is, and by a child of a node translated by (10, 0, 0).
  // Positions (0,0,0), (1,0,0), (0,1,0) as little-endian floats, base64.
  const std::string gltf = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
    "nodes": [{"mesh": 0}, {"translation": [10, 0, 0], "children": [2]}, {"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0, 0, 0], "max": [1, 1, 0]}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "buffers": [{"byteLength": 36,
                 "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})";
  TempTree dir(TempTree::Files{{"two.gltf", gltf}});
  const std::vector<glm::vec3> raw = pn::load_model_triangles(dir.root() / "two.gltf");
  REQUIRE(raw.size() == 6);
  const Bounds b = bounds_of(raw);
  CHECK(b.lo == glm::vec3(0, 0, 0));
  CHECK(b.hi == glm::vec3(11, 1, 0));
}

TEST_CASE("model scenes: each bad file is one line naming the file and what was expected") {
  TempTree dir(TempTree::Files{
      {"empty.obj", ""},
      {"lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\np 1\n"},
      {"vertices.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"},
      {"point.obj", "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n"},
      {"cube.obj", kCubeObj},
      {"text.glb", "this is not a binary glTF file\n"},
      {"sub/keep", ""},
  });
  const fs::path root = dir.root();
  CHECK(error_of(root / "nope.obj") == quoted(root / "nope.obj") + "no such file");
  CHECK(error_of(root / "sub") == quoted(root / "sub") + "is a directory, expected a mesh file");
  CHECK(error_of(root / "empty.obj") ==
        quoted(root / "empty.obj") + "empty file, expected a mesh file (glTF, OBJ or another format Assimp reads)");
  CHECK(error_of("/dev/null") == quoted("/dev/null") + "not a regular file, expected a mesh file");
  const std::string no_triangles = "no triangles (points and lines are ignored), expected a triangle mesh";
  CHECK(error_of(root / "lines.obj") == quoted(root / "lines.obj") + no_triangles);
  CHECK(error_of(root / "vertices.obj") == quoted(root / "vertices.obj") + no_triangles);
  CHECK(error_of(root / "point.obj") ==
        quoted(root / "point.obj") + "zero extent (every vertex at one point), expected a model with a size");
  CHECK(error_of(root / "cube.obj", {.max_triangles = 11}) ==
        quoted(root / "cube.obj") + "12 triangles, expected at most 11");
  CHECK(error_of(root / "cube.obj", {.max_file_bytes = 100}) ==
        quoted(root / "cube.obj") + std::to_string(fs::file_size(root / "cube.obj")) + " bytes, expected at most 100");
  CHECK_THAT(error_of(root / "text.glb"), Catch::StartsWith(quoted(root / "text.glb") + "not a mesh file Assimp can read: "));
}

TEST_CASE("model scenes: the first half of the glTF engine is refused with Assimp's reason on the same line") {
  const std::string glb = bytes_of(kEngine);
  TempTree dir(TempTree::Files{{"half.glb", glb.substr(0, glb.size() / 2)}});
  const std::string message = error_of(dir.root() / "half.glb");
  const std::string prefix = quoted(dir.root() / "half.glb") + "not a mesh file Assimp can read: ";
  CHECK_THAT(message, Catch::StartsWith(prefix));
  CHECK(message.size() > prefix.size() + 5);  // Assimp said why
}

TEST_CASE("model scenes: an unreadable file is refused as such (skipped as root, who reads it anyway)") {
  TempTree dir(TempTree::Files{{"locked.obj", kCubeObj}});
  const fs::path file = dir.root() / "locked.obj";
  fs::permissions(file, fs::perms::none);
  if (std::ifstream(file)) {
    WARN("running as root: " << file << " stays readable; the permission case is not exercised");
    return;
  }
  CHECK(error_of(file) == quoted(file) + "cannot be read: Permission denied");
}

TEST_CASE("model scenes: vertices that are not finite are refused by the placement") {
  const std::vector<glm::vec3> bad = {{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}};
  CHECK_THROWS_WITH(pn::place_model_on_ground(bad, "x.obj"),
                    "model 'x.obj': a vertex coordinate is not finite, expected finite coordinates");
  const std::vector<glm::vec3> huge = {{-3e38f, 0, 0}, {3e38f, 0, 0}, {0, 1, 0}};  // extent beyond FLT_MAX
  const std::vector<glm::vec3> placed = pn::place_model_on_ground(huge, "x.obj");
  CHECK(placed[0].x == -4.0f);
  CHECK(placed[1].x == 4.0f);
}

TEST_CASE("model scenes: loading good and bad files writes nothing to stdout or stderr (Assimp logs nowhere)") {
  const std::string glb = bytes_of(kEngine);
  TempTree dir(TempTree::Files{{"half.glb", glb.substr(0, glb.size() / 2)}, {"text.obj", "nonsense\n"}});
  const fs::path captured = dir.root() / "captured.txt";
  std::fflush(stdout), std::fflush(stderr);
  const int saved_out = dup(1), saved_err = dup(2);
  const int sink = open(captured.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  REQUIRE(sink >= 0);
  dup2(sink, 1), dup2(sink, 2), close(sink);
  for (const fs::path& file : {kSpider, dir.root() / "half.glb", dir.root() / "text.obj"}) {
    try {
      pn::load_model_triangles(file);
    } catch (const pn::Error&) {
    }
  }
  std::fflush(stdout), std::fflush(stderr);
  dup2(saved_out, 1), dup2(saved_err, 2), close(saved_out), close(saved_err);
  CHECK(bytes_of(captured).empty());
}
