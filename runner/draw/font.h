// A TrueType font for the figures' labels (stb_truetype), loaded once from a
// file — by default Debian's DejaVu Sans (fonts-dejavu-core). One line of
// UTF-8 text at a time, rasterised into 8-bit coverage; Canvas::text blends it.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace pn {

inline constexpr const char* kDejaVuSansPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// One line of text as coverage (0 transparent .. 255 opaque), row-major, `width` × `height`.
// Column 0 / row 0 lie at (left, top) relative to the line box's top-left corner, the pen's start;
// the rectangle holds the line box (text_width × pixel_height) and every glyph's ink, so `left`
// and `top` are ≤ 0 where a glyph reaches past the pen's start or above the ascent.
// An empty text is 0 × 0.
struct TextCoverage {
  int left = 0, top = 0;
  int width = 0, height = 0;
  std::vector<unsigned char> alpha;
  unsigned char at(int x, int y) const { return alpha[static_cast<size_t>(y) * width + x]; }
};

class Font {
 public:
  // Reads and parses the font file. Throws Error naming the path and Debian's fonts-dejavu-core
  // when it is missing, unreadable or not a TrueType font.
  explicit Font(const std::filesystem::path& path = kDejaVuSansPath);
  ~Font();
  Font(Font&&) noexcept;
  Font& operator=(Font&&) noexcept;
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  const std::filesystem::path& path() const { return path_; }

  // `pixel_height` is the line box's height (ascent to descent), 1 to 1024; Error otherwise.
  // Rows from the top of the line box to the baseline.
  int baseline(int pixel_height) const;
  // The pen's advance over `utf8` (kerning included), rounded up: the width to lay text out by.
  int text_width(const std::string& utf8, int pixel_height) const;
  TextCoverage rasterise(const std::string& utf8, int pixel_height) const;

 private:
  struct Face;
  std::filesystem::path path_;
  std::unique_ptr<Face> face_;
};

}  // namespace pn
