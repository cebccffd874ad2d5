#include "draw/canvas.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

#include "core/error.h"
#include "core/format.h"
#include "core/write_file.h"

namespace pn {

Rgb signed_colour(float value, float limit) {
  if (!std::isfinite(limit) || !(limit > 0.0f))
    throw Error("signed map limit " + format_number("%g", limit) + ": expected a finite number > 0");
  if (!std::isfinite(value)) return kSignedNonFinite;
  const Rgb& end = value < 0.0f ? kSignedNegative : kSignedPositive;
  const float t = std::min(std::fabs(value) / limit, 1.0f);
  Rgb colour;
  for (int c = 0; c < 3; ++c)
    colour[c] = static_cast<unsigned char>(std::lround(kSignedZero[c] + (static_cast<float>(end[c]) - kSignedZero[c]) * t));
  return colour;
}

Canvas::Canvas(int width, int height, Rgb background)
    : width_(width), height_(height), pixels_(static_cast<size_t>(width) * height * 3) {
  fill(0, 0, width, height, background);
}

void Canvas::fill(int x, int y, int w, int h, Rgb colour, float alpha) {
  for (int py = std::max(y, 0); py < std::min(y + h, height_); ++py) {
    for (int px = std::max(x, 0); px < std::min(x + w, width_); ++px) blend(px, py, colour, alpha);
  }
}

void Canvas::blend(int x, int y, Rgb colour, float alpha) {
  unsigned char* p = &pixels_[(static_cast<size_t>(y) * width_ + x) * 3];
  for (int c = 0; c < 3; ++c) p[c] = static_cast<unsigned char>(std::lround(p[c] * (1 - alpha) + colour[c] * alpha));
}

Rgb Canvas::pixel(int x, int y) const {
  if (x < 0 || y < 0 || x >= width_ || y >= height_)
    throw Error("pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): outside the " + std::to_string(width_) +
                "x" + std::to_string(height_) + " canvas");
  const unsigned char* p = &pixels_[(static_cast<size_t>(y) * width_ + x) * 3];
  return {p[0], p[1], p[2]};
}

void Canvas::line(double x0, double y0, double x1, double y1, Rgb colour, int width, int dash) {
  const double length = std::hypot(x1 - x0, y1 - y0);
  const int steps = std::max(1, static_cast<int>(std::ceil(2.0 * length)));
  for (int i = 0; i <= steps; ++i) {
    const double t = static_cast<double>(i) / steps;
    if (dash > 0 && static_cast<int>(t * length / dash) % 2 == 1) continue;
    const int x = static_cast<int>(std::lround(x0 + t * (x1 - x0))) - width / 2;
    const int y = static_cast<int>(std::lround(y0 + t * (y1 - y0))) - width / 2;
    fill(x, y, width, width, colour);
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

void Canvas::signed_map(const Image& image, int channel, int x, int y, int scale, float limit) {
  signed_colour(0.0f, limit);  // refuses a bad limit before drawing anything
  for (int ty = 0; ty < image.height; ++ty)
    for (int tx = 0; tx < image.width; ++tx)
      fill(x + tx * scale, y + ty * scale, scale, scale, signed_colour(image.at(tx, ty, channel), limit));
}

PixelBox Canvas::colour_bar(const Font& font, int x, int y, int width, int height, float limit, int pixel_height, Rgb ink) {
  signed_colour(0.0f, limit);
  for (int row = 0; row < height; ++row) {
    const float value = limit * (1.0f - 2.0f * (static_cast<float>(row) + 0.5f) / static_cast<float>(height));
    fill(x, y + row, width, 1, signed_colour(value, limit));
  }
  outline(x - 1, y - 1, width + 2, height + 2, {120, 120, 120});
  const std::string magnitude = format_number("%g", limit);
  const int lx = x + width + 4;
  const PixelBox labels[] = {text(font, lx, y, "+" + magnitude, pixel_height, ink),
                        text(font, lx, y + height / 2 - pixel_height / 2, "0", pixel_height, ink),
                        text(font, lx, y + height - pixel_height, "\u2212" + magnitude, pixel_height, ink)};
  int x0 = x - 1, y0 = y - 1, x1 = x + width + 1, y1 = y + height + 1;
  for (const PixelBox& b : labels) {
    if (b.width == 0) continue;
    x0 = std::min(x0, b.x), y0 = std::min(y0, b.y);
    x1 = std::max(x1, b.x + b.width), y1 = std::max(y1, b.y + b.height);
  }
  return {x0, y0, x1 - x0, y1 - y0};
}

PixelBox Canvas::text(const Font& font, int x, int y, const std::string& text, int pixel_height, Rgb colour) {
  const TextCoverage coverage = font.rasterise(text, pixel_height);
  if (coverage.width == 0) return {x, y, 0, 0};
  // In 64 bits: a label far outside the canvas must not wrap around into it.
  const long long left = static_cast<long long>(x) + coverage.left, top = static_cast<long long>(y) + coverage.top;
  const long long x0 = std::max(left, 0LL), x1 = std::min(left + coverage.width, static_cast<long long>(width_));
  const long long y0 = std::max(top, 0LL), y1 = std::min(top + coverage.height, static_cast<long long>(height_));
  for (long long py = y0; py < y1; ++py)
    for (long long px = x0; px < x1; ++px) {
      const unsigned char a = coverage.at(static_cast<int>(px - left), static_cast<int>(py - top));
      if (a) blend(static_cast<int>(px), static_cast<int>(py), colour, static_cast<float>(a) / 255.0f);
    }
  return {static_cast<int>(std::clamp<long long>(left, INT_MIN, INT_MAX)),
          static_cast<int>(std::clamp<long long>(top, INT_MIN, INT_MAX)), coverage.width, coverage.height};
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

std::string Canvas::png() const {
  std::string bytes;
  const auto append = [](void* out, void* data, int size) {
    static_cast<std::string*>(out)->append(static_cast<const char*>(data), static_cast<size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &bytes, width_, height_, 3, pixels_.data(), width_ * 3))
    throw Error("PNG encoding failed");
  return bytes;
}

void Canvas::write_png(const std::filesystem::path& path) const {
  std::string bytes;
  try {
    bytes = png();
  } catch (const Error&) {
    throw Error("figure '" + path.string() + "': PNG encoding failed");
  }
  write_file_atomically(path, bytes);
}

}  // namespace pn
