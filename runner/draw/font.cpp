#include "draw/font.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#include <stb/stb_truetype.h>

#include "core/error.h"
#include "core/utf8.h"

namespace pn {

struct Font::Face {
  std::vector<unsigned char> data;  // stbtt_fontinfo points into it: allocated once, never resized
  stbtt_fontinfo info{};
};

namespace {

std::string where(const std::filesystem::path& path) { return "font '" + path.string() + "'"; }

std::string package_hint() { return " (the labels' font, DejaVu Sans, is Debian's fonts-dejavu-core)"; }

// stb_truetype trusts its input: the table directory at `offset`, and every table it names, must lie
// inside the file before stbtt_InitFont reads them.
bool tables_inside(const std::vector<unsigned char>& data, size_t offset) {
  const auto u32 = [&](size_t at) {
    return (static_cast<size_t>(data[at]) << 24) | (static_cast<size_t>(data[at + 1]) << 16) |
           (static_cast<size_t>(data[at + 2]) << 8) | data[at + 3];
  };
  if (offset + 12 > data.size()) return false;
  const size_t tables = (static_cast<size_t>(data[offset + 4]) << 8) | data[offset + 5];
  if (offset + 12 + 16 * tables > data.size()) return false;
  for (size_t t = 0; t < tables; ++t) {
    const size_t entry = offset + 12 + 16 * t, start = u32(entry + 8), length = u32(entry + 12);
    if (start > data.size() || length > data.size() - start) return false;
  }
  return true;
}

float scale_for(const stbtt_fontinfo& info, int pixel_height) {
  if (pixel_height < 1 || pixel_height > 1024)
    throw Error("text pixel height " + std::to_string(pixel_height) + ": expected 1 to 1024");
  return stbtt_ScaleForPixelHeight(&info, static_cast<float>(pixel_height));
}

// A glyph placed on the line: its index and the pen's x where it starts.
struct Placed {
  int glyph;
  float pen;
};

// Lays `text` out from pen 0; returns the glyphs and sets `end` to the pen's final x.
std::vector<Placed> lay_out(const stbtt_fontinfo& info, const std::string& text, float scale, float& end) {
  std::vector<Placed> placed;
  float pen = 0.0f;
  int previous = -1;
  for (char32_t c : decode_utf8(text)) {
    const int glyph = stbtt_FindGlyphIndex(&info, static_cast<int>(c));
    if (previous >= 0) pen += scale * static_cast<float>(stbtt_GetGlyphKernAdvance(&info, previous, glyph));
    placed.push_back({glyph, pen});
    int advance = 0, bearing = 0;
    stbtt_GetGlyphHMetrics(&info, glyph, &advance, &bearing);
    pen += scale * static_cast<float>(advance);
    previous = glyph;
  }
  end = pen;
  return placed;
}

}  // namespace

Font::Font(const std::filesystem::path& path) : path_(path), face_(std::make_unique<Face>()) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(where(path) + ": no such file" + package_hint());
  std::ifstream in(path, std::ios::binary);
  if (in) face_->data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (!in || in.bad()) throw Error(where(path) + ": cannot be read" + package_hint());
  const int offset = face_->data.size() < 16 ? -1 : stbtt_GetFontOffsetForIndex(face_->data.data(), 0);
  if (offset < 0 || !tables_inside(face_->data, static_cast<size_t>(offset)) ||
      !stbtt_InitFont(&face_->info, face_->data.data(), offset))
    throw Error(where(path) + ": not a TrueType font" + package_hint());
}

Font::~Font() = default;
Font::Font(Font&&) noexcept = default;
Font& Font::operator=(Font&&) noexcept = default;

int Font::baseline(int pixel_height) const {
  const float scale = scale_for(face_->info, pixel_height);
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&face_->info, &ascent, &descent, &gap);
  return static_cast<int>(std::lround(scale * static_cast<float>(ascent)));
}

int Font::text_width(const std::string& utf8, int pixel_height) const {
  float end = 0.0f;
  lay_out(face_->info, utf8, scale_for(face_->info, pixel_height), end);
  return static_cast<int>(std::ceil(end));
}

TextCoverage Font::rasterise(const std::string& utf8, int pixel_height) const {
  const stbtt_fontinfo& info = face_->info;
  const float scale = scale_for(info, pixel_height);
  float end = 0.0f;
  const std::vector<Placed> placed = lay_out(info, utf8, scale, end);
  TextCoverage out;
  if (placed.empty()) return out;
  const int base = baseline(pixel_height);

  // Each glyph's box on the line (pen at a whole pixel plus a sub-pixel shift), and their union with the line box.
  struct GlyphBox {
    int x0, y0, x1, y1;
    float shift;
  };
  std::vector<GlyphBox> boxes;
  int x0 = 0, y0 = 0, x1 = static_cast<int>(std::ceil(end)), y1 = pixel_height;
  for (const Placed& p : placed) {
    const float whole = std::floor(p.pen);
    GlyphBox b{0, 0, 0, 0, p.pen - whole};
    stbtt_GetGlyphBitmapBoxSubpixel(&info, p.glyph, scale, scale, b.shift, 0.0f, &b.x0, &b.y0, &b.x1, &b.y1);
    const int dx = static_cast<int>(whole);
    b.x0 += dx, b.x1 += dx, b.y0 += base, b.y1 += base;
    boxes.push_back(b);
    if (b.x1 > b.x0 && b.y1 > b.y0) {
      x0 = std::min(x0, b.x0), y0 = std::min(y0, b.y0);
      x1 = std::max(x1, b.x1), y1 = std::max(y1, b.y1);
    }
  }
  out.left = x0, out.top = y0, out.width = x1 - x0, out.height = y1 - y0;
  out.alpha.assign(static_cast<size_t>(out.width) * out.height, 0);

  // Glyph boxes overlap (kerning, bearings): each is drawn on its own, then combined by max.
  std::vector<unsigned char> glyph;
  for (size_t i = 0; i < placed.size(); ++i) {
    const GlyphBox& b = boxes[i];
    const int w = b.x1 - b.x0, h = b.y1 - b.y0;
    if (w <= 0 || h <= 0) continue;
    glyph.assign(static_cast<size_t>(w) * h, 0);
    stbtt_MakeGlyphBitmapSubpixel(&info, glyph.data(), w, h, w, scale, scale, b.shift, 0.0f, placed[i].glyph);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        unsigned char& a = out.alpha[static_cast<size_t>(b.y0 - y0 + y) * out.width + (b.x0 - x0 + x)];
        a = std::max(a, glyph[static_cast<size_t>(y) * w + x]);
      }
  }
  return out;
}

}  // namespace pn
