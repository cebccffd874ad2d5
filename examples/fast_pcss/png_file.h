// PNG output: 8-bit RGB from float images, written whole or not at all.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace example {

// An image read back from GL: rows from the bottom (GL's order), `channels` floats a pixel.
struct FloatImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> texels;
};

// 8-bit RGB PNG bytes, top row first: each channel round(255 * clamp(v, 0, 1)) (non-finite: 0);
// a one-channel image becomes grey.
std::string encode_png(const FloatImage& image);

// Writes every (path, bytes) pair beside its path first, then renames them in place: a failure
// leaves none of them half-written. Throws std::runtime_error naming the path.
void write_files(const std::vector<std::pair<std::filesystem::path, std::string>>& files);

}  // namespace example
