// A float image on the CPU: what fixtures produce, what the GPU result is read
// back into, and what references compute. Row-major, origin top-left (SPEC §3).
#pragma once

#include <cstddef>
#include <vector>

namespace pn {

struct Image {
  int width = 0;
  int height = 0;
  int channels = 1;
  std::vector<float> texels;  // width * height * channels

  Image() = default;
  Image(int w, int h, int c = 1, float fill = 0.0f)
      : width(w), height(h), channels(c), texels(static_cast<size_t>(w) * h * c, fill) {}

  float& at(int x, int y, int c = 0) { return texels[index(x, y, c)]; }
  float at(int x, int y, int c = 0) const { return texels[index(x, y, c)]; }

 private:
  size_t index(int x, int y, int c) const {
    return (static_cast<size_t>(y) * width + x) * channels + c;
  }
};

}  // namespace pn
