#include "core/utf8.h"

namespace pn {
namespace {

// The code point at byte i and its length in bytes; length 0 for a malformed sequence there.
struct Utf8Point {
  char32_t code = 0;
  int length = 0;
};

Utf8Point utf8_point(const std::string& utf8, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(utf8[k]); };
  const unsigned char b = byte(i);
  const int length = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xe ? 3 : (b >> 3) == 0x1e ? 4 : 0;
  char32_t c = length == 1 ? b : length == 2 ? (b & 0x1f) : length == 3 ? (b & 0x0f) : (b & 0x07);
  bool ok = length > 0 && i + length <= utf8.size();
  for (int k = 1; ok && k < length; ++k) {
    ok = (byte(i + k) & 0xc0) == 0x80;
    c = (c << 6) | (byte(i + k) & 0x3f);
  }
  // Overlong forms, surrogates and values past U+10FFFF are malformed too.
  static constexpr char32_t kSmallest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (ok && (c < kSmallest[length] || (c >= 0xd800 && c <= 0xdfff) || c > 0x10ffff)) ok = false;
  return ok ? Utf8Point{c, length} : Utf8Point{};
}

}  // namespace

std::vector<char32_t> decode_utf8(const std::string& utf8) {
  std::vector<char32_t> out;
  for (size_t i = 0; i < utf8.size();) {
    const Utf8Point p = utf8_point(utf8, i);
    out.push_back(p.length > 0 ? p.code : U'\uFFFD');
    i += p.length > 0 ? static_cast<size_t>(p.length) : 1;
  }
  return out;
}

bool valid_utf8(const std::string& text) {
  for (size_t i = 0; i < text.size();) {
    const Utf8Point p = utf8_point(text, i);
    if (p.length == 0) return false;
    i += static_cast<size_t>(p.length);
  }
  return true;
}

}  // namespace pn
