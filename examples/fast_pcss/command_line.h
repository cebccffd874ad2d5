// The command line both examples share (fast_pcss, fast_pcss_vulkan): the model, where the two
// pictures go, the screen size and the bias, each checked before any GPU work.
#pragma once

#include <filesystem>

namespace example {

struct CommonOptions {
  std::filesystem::path model = "/usr/share/assimp/models/OBJ/spider.obj";  // Debian's assimp-testmodels
  std::filesystem::path out;  // a directory, or a .png file for the lit image
  int size = 512;             // screen N x N (the shadow map stays kShadowMapSize)
  float bias = 0.02f;         // Fast PCSS's depth bias (scene_setup.h's kDepthBias)
};

// The usage lines of the four options, `out` the default --out.
std::string common_usage(const std::string& out);

// When argv[i] is --model, --out, --size or --bias: reads it and its value into `o`, moves `i`
// past the value and returns true; false for any other flag. Throws std::invalid_argument for a
// missing value or a number that does not parse.
bool read_common_option(int argc, char** argv, int& i, CommonOptions& o);

// Throws std::invalid_argument unless the size is 16..4096 and the bias a finite number >= 0.
void check_common_options(const CommonOptions& o);

// Where the two pictures go: --out F.png writes F.png and F_visibility.png; --out DIR writes
// DIR/<model>_fast_pcss_lit.png and _visibility.png. Throws std::invalid_argument unless the
// directory exists or can be made and the lit image's name is not a directory; made only once
// there is something to write (make_directory).
struct Outputs {
  std::filesystem::path directory, lit, visibility;
};
Outputs plan_outputs(const CommonOptions& o);
void make_directory(const std::filesystem::path& directory);  // throws std::runtime_error

}  // namespace example
