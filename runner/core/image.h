// A float image on the CPU: what fixtures produce, what the GPU result is read
// back into, and what references compute. Row-major, origin top-left (SPEC §3).
#pragma once

#include <algorithm>
#include <cmath>
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

// max(floor, the largest |v| over the finite texels): the scale of float-rounding bounds.
inline float largest_finite_magnitude(const Image& image, float floor) {
  float largest = floor;
  for (float v : image.texels)
    if (std::isfinite(v)) largest = std::max(largest, std::fabs(v));
  return largest;
}

// Channels [first, first + count) of `image`, as an image of their own.
inline Image channels_of(const Image& image, int first, int count) {
  Image out(image.width, image.height, count);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < count; ++c) out.at(x, y, c) = image.at(x, y, first + c);
  return out;
}

// The top-left width × height texels of `image`.
inline Image top_left(const Image& image, int width, int height) {
  Image out(width, height, image.channels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < image.channels; ++c) out.at(x, y, c) = image.at(x, y, c);
  return out;
}

// The rows in reverse order: GL's bottom-up framebuffer rows as a top-down picture.
inline Image flip_rows(const Image& image) {
  Image out(image.width, image.height, image.channels);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < image.channels; ++c) out.at(x, y, c) = image.at(x, image.height - 1 - y, c);
  return out;
}

}  // namespace pn
