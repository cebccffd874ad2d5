// Fuzz target: the model loader's entry point, make_model_scene
// (scene/model), as `penumbra render --model FILE` calls it: the file's
// checks, Assimp's import, the triangle count and placement on the ground.
//
// Input: a first line naming the file's extension ("obj\n", "glb\n": Assimp
// picks its importer by extension, then by content), then the file's bytes;
// without such a line, the whole input, its extension picked by its first
// byte. A pn::Error naming the file is the expected answer to a file that is
// not a usable mesh.
#include <string>

#include "core/error.h"
#include "fuzz_input.h"
#include "scene/model.h"

namespace {

const char* const kExtensions[] = {"obj", "gltf", "glb", "stl", "ply", "off", "dae", "fbx", "3ds", "x"};
constexpr size_t kExtensionCount = sizeof kExtensions / sizeof kExtensions[0];

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const pn::fuzz::ScratchDir scratch("model");
  scratch.clear();
  const std::string input = pn::fuzz::as_text(data, size);
  const size_t newline = input.find('\n');
  const std::string first = input.substr(0, newline);
  const char* extension = size == 0 ? kExtensions[0] : kExtensions[data[0] % kExtensionCount];
  std::string bytes = input;
  for (const char* known : kExtensions)
    if (first == known && newline != std::string::npos) extension = known, bytes = input.substr(newline + 1);
  const auto file = scratch.write(std::string("model.") + extension, bytes);
  try {
    const pn::Scene scene = pn::make_model_scene(file, 16);
    (void)scene.triangles();
  } catch (const pn::Error&) {
    // refused with one line naming the file
  }
  return 0;
}
