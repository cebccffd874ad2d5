#include "figures/canvas.h"

#include <algorithm>
#include <cmath>
#include <string>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

#include "core/error.h"
#include "core/write_file.h"

namespace pn {

Canvas::Canvas(int width, int height, Rgb background)
    : width_(width), height_(height), pixels_(static_cast<size_t>(width) * height * 3) {
  fill(0, 0, width, height, background);
}

void Canvas::fill(int x, int y, int w, int h, Rgb colour, float alpha) {
  for (int py = std::max(y, 0); py < std::min(y + h, height_); ++py) {
    for (int px = std::max(x, 0); px < std::min(x + w, width_); ++px) {
      unsigned char* p = &pixels_[(static_cast<size_t>(py) * width_ + px) * 3];
      for (int c = 0; c < 3; ++c) p[c] = static_cast<unsigned char>(std::lround(p[c] * (1 - alpha) + colour[c] * alpha));
    }
  }
}

void Canvas::outline(int x, int y, int w, int h, Rgb colour, int thickness) {
  fill(x, y, w, thickness, colour);
  fill(x, y + h - thickness, w, thickness, colour);
  fill(x, y, thickness, h, colour);
  fill(x + w - thickness, y, thickness, h, colour);
}

void Canvas::grey(const Image& image, int channel, int x, int y, int scale, float lo, float hi, Rgb nonfinite) {
  for (int ty = 0; ty < image.height; ++ty) {
    for (int tx = 0; tx < image.width; ++tx) {
      const float v = image.at(tx, ty, channel);
      Rgb colour = nonfinite;
      if (std::isfinite(v)) {
        const float t = std::clamp((v - lo) / (hi - lo), 0.0f, 1.0f);
        const auto g = static_cast<unsigned char>(std::lround(t * 255.0f));
        colour = {g, g, g};
      }
      fill(x + tx * scale, y + ty * scale, scale, scale, colour);
    }
  }
}

void Canvas::rgb(const Image& image, int x, int y, int scale) {
  for (int v = 0; v < image.height; ++v)
    for (int u = 0; u < image.width; ++u) {
      Rgb colour;
      for (int c = 0; c < 3; ++c) {
        const float value = image.at(u, v, std::min(c, image.channels - 1));
        colour[c] = static_cast<unsigned char>(std::lround(255.0f * std::clamp(std::isfinite(value) ? value : 0.0f, 0.0f, 1.0f)));
      }
      fill(x + u * scale, y + v * scale, scale, scale, colour);
    }
}

void Canvas::write_png(const std::filesystem::path& path) const {
  std::string png;
  const auto append = [](void* out, void* data, int size) {
    static_cast<std::string*>(out)->append(static_cast<const char*>(data), static_cast<size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &png, width_, height_, 3, pixels_.data(), width_ * 3))
    throw Error("figure '" + path.string() + "': PNG encoding failed");
  write_file_atomically(path, png);
}

}  // namespace pn
