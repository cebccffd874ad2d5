// A small RGB picture for the docs' figures: filled and outlined rectangles,
// grey-scale images scaled up, written as PNG (stb_image_write).
#pragma once

#include <array>
#include <filesystem>
#include <vector>

#include "core/image.h"

namespace pn {

using Rgb = std::array<unsigned char, 3>;

class Canvas {
 public:
  Canvas(int width, int height, Rgb background);
  int width() const { return width_; }
  int height() const { return height_; }

  // Blends `colour` over the rectangle with opacity `alpha` in [0, 1]; clipped to the canvas.
  void fill(int x, int y, int w, int h, Rgb colour, float alpha = 1.0f);
  void outline(int x, int y, int w, int h, Rgb colour, int thickness = 1);
  // Draws channel `channel` of `image`, each texel a scale×scale block, grey from lo (black) to hi (white);
  // non-finite values are drawn in `nonfinite`.
  void grey(const Image& image, int channel, int x, int y, int scale, float lo, float hi, Rgb nonfinite);

  // Draws a 3-channel image of values in [0, 1] (clamped), each texel a scale×scale block.
  void rgb(const Image& image, int x, int y, int scale);

  // Throws Error naming the path when it cannot be written.
  void write_png(const std::filesystem::path& path) const;

 private:
  int width_, height_;
  std::vector<unsigned char> pixels_;
};

}  // namespace pn
