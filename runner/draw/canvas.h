// A small RGB picture for the docs' figures: filled and outlined rectangles,
// grey-scale, colour and signed (diverging) images scaled up, text labels
// (draw/font.h), written as PNG (stb_image_write).
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "core/image.h"
#include "draw/font.h"

namespace pn {

using Rgb = std::array<unsigned char, 3>;

// A rectangle of pixels, [x, x + width) × [y, y + height), in canvas coordinates (it may reach outside).
struct PixelBox {
  int x = 0, y = 0, width = 0, height = 0;
};

// The signed map: a diverging map, linear in sRGB from white at 0 to kSignedNegative at -limit and
// kSignedPositive at +limit, saturating beyond; NaN and ±Inf are kSignedNonFinite.
inline constexpr Rgb kSignedNegative{33, 102, 172};
inline constexpr Rgb kSignedZero{255, 255, 255};
inline constexpr Rgb kSignedPositive{178, 24, 43};
inline constexpr Rgb kSignedNonFinite{220, 0, 180};
// The colour of `value`; `limit` must be finite and > 0 (Error otherwise).
Rgb signed_colour(float value, float limit);

class Canvas {
 public:
  Canvas(int width, int height, Rgb background);
  int width() const { return width_; }
  int height() const { return height_; }

  // Blends `colour` over the rectangle with opacity `alpha` in [0, 1]; clipped to the canvas.
  void fill(int x, int y, int w, int h, Rgb colour, float alpha = 1.0f);
  void outline(int x, int y, int w, int h, Rgb colour, int thickness = 1);
  // A straight line from (x0, y0) to (x1, y1), `width` pixels wide (squares stamped every half
  // pixel along it); `dash` > 0: drawn `dash` pixels, left `dash` pixels, and so on. Clipped.
  void line(double x0, double y0, double x1, double y1, Rgb colour, int width = 2, int dash = 0);
  // Draws channel `channel` of `image`, each texel a scale×scale block, grey from lo (black) to hi (white);
  // non-finite values are drawn in `nonfinite`.
  void grey(const Image& image, int channel, int x, int y, int scale, float lo, float hi, Rgb nonfinite);

  // Draws a 3-channel image of values in [0, 1] (clamped), each texel a scale×scale block.
  void rgb(const Image& image, int x, int y, int scale);

  // Draws channel `channel` of `image` in the signed map (signed_colour), each texel a scale×scale block.
  void signed_map(const Image& image, int channel, int x, int y, int scale, float limit);
  // A vertical bar of the signed map, +limit at the top row and -limit at the bottom, outlined, with
  // the labels "+limit", "0" and "−limit" (printf %g) at its right in `ink`. Returns the box it drew in.
  PixelBox colour_bar(const Font& font, int x, int y, int width, int height, float limit, int pixel_height, Rgb ink);

  // Draws one line of UTF-8 text in `colour`, glyph coverage alpha-blended, with the top-left corner
  // of its line box (font.text_width(text) × pixel_height, baseline font.baseline(pixel_height) rows
  // down) at (x, y); clipped to the canvas. Returns the box that holds every pixel it may change
  // (unclipped; empty, 0 × 0 at (x, y), for an empty text).
  PixelBox text(const Font& font, int x, int y, const std::string& text, int pixel_height, Rgb colour);

  // The pixel at (x, y); Error outside the canvas.
  Rgb pixel(int x, int y) const;

  // Throws Error naming the path when it cannot be written.
  void write_png(const std::filesystem::path& path) const;
  // The canvas encoded as a PNG file's bytes (what write_png writes); Error when encoding fails.
  std::string png() const;

 private:
  void blend(int x, int y, Rgb colour, float alpha);  // (x, y) inside the canvas
  int width_, height_;
  std::vector<unsigned char> pixels_;
};

}  // namespace pn
