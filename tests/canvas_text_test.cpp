// Labels and the signed colour map on the figures' Canvas: text changes only
// pixels inside the box it reports and is clipped at the canvas's edges; the
// diverging map's end colours, zero and non-finite colour are exact.
#include <catch2/catch.hpp>

#include <climits>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>

#include "core/error.h"
#include "core/utf8.h"
#include "draw/canvas.h"
#include "draw/font.h"
#include "temp_tree.h"

namespace {

constexpr pn::Rgb kWhite{255, 255, 255};
constexpr pn::Rgb kInk{10, 20, 30};

bool inside(const pn::PixelBox& b, int x, int y) { return x >= b.x && x < b.x + b.width && y >= b.y && y < b.y + b.height; }

// Pixels that differ from the background, and how many of them lie outside `box`.
struct Changes {
  int changed = 0, outside = 0;
};
Changes changes(const pn::Canvas& canvas, const pn::PixelBox& box, pn::Rgb background) {
  Changes out;
  for (int y = 0; y < canvas.height(); ++y)
    for (int x = 0; x < canvas.width(); ++x)
      if (canvas.pixel(x, y) != background) {
        ++out.changed;
        if (!inside(box, x, y)) ++out.outside;
      }
  return out;
}

const pn::Font& dejavu() {
  static const pn::Font font;  // read once for the whole file; never modified
  return font;
}

}  // namespace

TEST_CASE("text: every pixel it changes lies inside the box it reports, which holds its line box") {
  const pn::Font& font = dejavu();
  for (const std::string label : {"Penumbra", "gjy|Q_", "\u00b10.05 \u03c3 \u2212"}) {
    for (int height : {9, 14, 31}) {
      pn::Canvas canvas(260, 80, kWhite);
      const pn::PixelBox box = canvas.text(font, 12, 20, label, height, kInk);
      const Changes c = changes(canvas, box, kWhite);
      INFO(label << " at " << height << " px: box " << box.x << "," << box.y << " " << box.width << "x" << box.height);
      CHECK(c.changed > 0);
      CHECK(c.outside == 0);
      CHECK(box.x <= 12);
      CHECK(box.y <= 20);
      CHECK(box.x + box.width >= 12 + font.text_width(label, height));
      CHECK(box.y + box.height >= 20 + height);
      // Coverage is blended: fully covered pixels (stems, at 14 px and up) are the ink itself.
      bool ink = false;
      for (int y = 0; y < canvas.height(); ++y)
        for (int x = 0; x < canvas.width(); ++x) ink = ink || canvas.pixel(x, y) == kInk;
      if (height >= 14) CHECK(ink);
    }
  }
}

TEST_CASE("text: \"WWW\" is wider than \"iii\", in text_width and in the box drawn") {
  const pn::Font& font = dejavu();
  CHECK(font.text_width("WWW", 16) > font.text_width("iii", 16));
  CHECK(font.text_width("WWW", 16) > 2 * font.text_width("iii", 16));
  pn::Canvas canvas(200, 40, kWhite);
  CHECK(canvas.text(font, 4, 4, "WWW", 16, kInk).width > canvas.text(font, 4, 20, "iii", 16, kInk).width);
  // Wider at a larger height too.
  CHECK(font.text_width("WWW", 32) > font.text_width("WWW", 16));
}

TEST_CASE("text: an empty string draws nothing, reports an empty box and has width 0") {
  const pn::Font& font = dejavu();
  pn::Canvas canvas(40, 30, kWhite);
  const pn::PixelBox box = canvas.text(font, 5, 6, "", 14, kInk);
  CHECK(box.width == 0);
  CHECK(box.height == 0);
  CHECK(font.text_width("", 14) == 0);
  CHECK(changes(canvas, box, kWhite).changed == 0);
  CHECK(font.rasterise("", 14).alpha.empty());
}

TEST_CASE("text: across the canvas's edges it changes exactly the pixels of the unclipped drawing, clipped") {
  // The small canvas is the window [100, 140) × [80, 110) of the large one.
  const pn::Font& font = dejavu();
  const int ox = 100, oy = 80;
  for (auto [x, y] : {std::pair{-7, -5}, std::pair{30, 22}, std::pair{-20, 10}, std::pair{15, -12}, std::pair{-3, 25}}) {
    pn::Canvas small(40, 30, kWhite), large(300, 200, kWhite);
    small.text(font, x, y, "Wgj\u00c9", 18, kInk);
    large.text(font, x + ox, y + oy, "Wgj\u00c9", 18, kInk);
    int mismatched = 0, changed = 0;
    for (int py = 0; py < small.height(); ++py)
      for (int px = 0; px < small.width(); ++px) {
        mismatched += small.pixel(px, py) != large.pixel(px + ox, py + oy);
        changed += small.pixel(px, py) != kWhite;
      }
    INFO("text at (" << x << ", " << y << ")");
    CHECK(mismatched == 0);
    CHECK(changed > 0);
  }
}

TEST_CASE("text: wholly outside the canvas, even at extreme positions, it changes no pixel and does not crash") {
  const pn::Font& font = dejavu();
  for (auto [x, y] : {std::pair{-1000, 5}, std::pair{5, 10000}, std::pair{-200, -200}, std::pair{40, 0},
                      std::pair{0, 30}, std::pair{INT_MIN, INT_MIN}, std::pair{INT_MAX, INT_MAX}}) {
    pn::Canvas canvas(40, 30, kWhite);
    canvas.text(font, x, y, "WWW gjy", 20, kInk);
    INFO("text at (" << x << ", " << y << ")");
    CHECK(changes(canvas, {0, 0, 0, 0}, kWhite).changed == 0);
  }
}

TEST_CASE("font: a moved font still draws the same text") {
  pn::Font first;
  const pn::TextCoverage before = first.rasterise("Move", 20);
  const pn::Font second(std::move(first));
  const pn::TextCoverage after = second.rasterise("Move", 20);
  CHECK(after.width == before.width);
  CHECK(after.alpha == before.alpha);
}

TEST_CASE("font: UTF-8 is decoded to code points; a malformed sequence becomes U+FFFD") {
  CHECK(pn::decode_utf8("a\u00b1\u2212\U0001f600") == std::vector<char32_t>{U'a', 0xb1, 0x2212, 0x1f600});
  CHECK(pn::decode_utf8("\xff" "a") == std::vector<char32_t>{0xfffd, U'a'});
  CHECK(pn::decode_utf8("\xe2\x88") == std::vector<char32_t>{0xfffd, 0xfffd});  // truncated
  CHECK(pn::decode_utf8("\xc0\xaf") == std::vector<char32_t>{0xfffd, 0xfffd});  // overlong '/'
}

TEST_CASE("valid_utf8 accepts well-formed UTF-8 and refuses what decode_utf8 replaces") {
  CHECK(pn::valid_utf8(""));
  CHECK(pn::valid_utf8("render/m\u00b1\u2212\U0001f600.obj"));
  CHECK(pn::valid_utf8("\xef\xbf\xbd"));                // U+FFFD itself is a code point like any other
  CHECK_FALSE(pn::valid_utf8("m\xff.obj"));               // a byte no sequence starts with
  CHECK_FALSE(pn::valid_utf8("\xe2\x88"));               // truncated
  CHECK_FALSE(pn::valid_utf8("\xc0\xaf"));               // overlong '/'
  CHECK_FALSE(pn::valid_utf8("\xed\xa0\x80"));          // a surrogate, U+D800
  CHECK_FALSE(pn::valid_utf8("\xf4\x90\x80\x80"));     // past U+10FFFF
}

TEST_CASE("negative: a missing font file is a one-line Error naming the path and fonts-dejavu-core") {
  try {
    pn::Font font("/no/such/dir/DejaVuSans.ttf");
    FAIL("no error");
  } catch (const pn::Error& e) {
    const std::string message = e.what();
    CHECK_THAT(message, Catch::Contains("'/no/such/dir/DejaVuSans.ttf'") && Catch::Contains("fonts-dejavu-core"));
    CHECK(message.find('\n') == std::string::npos);
  }
}

TEST_CASE("negative: an empty file, a short file and a text file are refused as not TrueType fonts") {
  const pn::test::TempTree tree({{"empty.ttf", ""}, {"short.ttf", "\x00\x01"}, {"text.ttf", std::string(4096, 'x')},
                                 {"tables.ttf", std::string("\x00\x01\x00\x00\xff\xff", 6) + std::string(64, '\0')}});
  for (const char* name : {"empty.ttf", "short.ttf", "text.ttf", "tables.ttf"}) {
    INFO(name);
    CHECK_THROWS_WITH(pn::Font(tree.root() / name), Catch::Contains(name) && Catch::Contains("not a TrueType font"));
  }
}

TEST_CASE("negative: text pixel heights of 0 and above 1024 are refused") {
  pn::Canvas canvas(10, 10, kWhite);
  CHECK_THROWS_WITH(canvas.text(dejavu(), 0, 0, "a", 0, kInk), Catch::Contains("text pixel height 0: expected 1 to 1024"));
  CHECK_THROWS_AS(dejavu().text_width("a", 1025), pn::Error);
}

TEST_CASE("signed map: exactly the end colours at -limit, +limit and beyond, white at 0 and -0") {
  const float limit = 0.05f;
  CHECK(pn::signed_colour(-limit, limit) == pn::kSignedNegative);
  CHECK(pn::signed_colour(-3 * limit, limit) == pn::kSignedNegative);
  CHECK(pn::signed_colour(-std::numeric_limits<float>::max(), limit) == pn::kSignedNegative);
  CHECK(pn::signed_colour(limit, limit) == pn::kSignedPositive);
  CHECK(pn::signed_colour(7 * limit, limit) == pn::kSignedPositive);
  CHECK(pn::signed_colour(std::numeric_limits<float>::max(), limit) == pn::kSignedPositive);
  CHECK(pn::signed_colour(0.0f, limit) == pn::Rgb{255, 255, 255});
  CHECK(pn::signed_colour(-0.0f, limit) == pn::Rgb{255, 255, 255});
}

TEST_CASE("signed map: NaN, +Inf and -Inf are the documented magenta") {
  CHECK(pn::kSignedNonFinite == pn::Rgb{220, 0, 180});
  CHECK(pn::signed_colour(std::nanf(""), 1.0f) == pn::kSignedNonFinite);
  CHECK(pn::signed_colour(std::numeric_limits<float>::infinity(), 1.0f) == pn::kSignedNonFinite);
  CHECK(pn::signed_colour(-std::numeric_limits<float>::infinity(), 1.0f) == pn::kSignedNonFinite);
}

TEST_CASE("signed map: half the limit is half way from white to the end colour; the sign picks the side") {
  const pn::Rgb half = pn::signed_colour(0.5f, 1.0f), minus = pn::signed_colour(-0.5f, 1.0f);
  for (int c = 0; c < 3; ++c) {
    CHECK(std::abs(half[c] - (255 + pn::kSignedPositive[c]) / 2.0) <= 0.5);
    CHECK(std::abs(minus[c] - (255 + pn::kSignedNegative[c]) / 2.0) <= 0.5);
  }
  CHECK(half[0] > half[2]);    // red side
  CHECK(minus[2] > minus[0]);  // blue side
}

TEST_CASE("signed map: each texel is a scale x scale block of its colour") {
  pn::Image image(4, 1, 2, 0.0f);
  const float values[] = {-2.0f, 0.0f, 0.25f, std::nanf("")};
  for (int x = 0; x < 4; ++x) image.at(x, 0, 1) = values[x];
  pn::Canvas canvas(14, 5, kWhite);
  canvas.signed_map(image, 1, 1, 1, 3, 1.0f);
  for (int x = 0; x < 4; ++x)
    for (int dy = 0; dy < 3; ++dy)
      for (int dx = 0; dx < 3; ++dx) CHECK(canvas.pixel(1 + 3 * x + dx, 1 + dy) == pn::signed_colour(values[x], 1.0f));
  CHECK(canvas.pixel(0, 0) == kWhite);
  CHECK(canvas.pixel(13, 4) == kWhite);
}

TEST_CASE("negative: a signed map limit of 0, below 0, NaN or Inf is refused") {
  for (float limit : {0.0f, -1.0f, std::nanf(""), std::numeric_limits<float>::infinity()}) {
    INFO(limit);
    CHECK_THROWS_WITH(pn::signed_colour(0.0f, limit), Catch::Contains("signed map limit") && Catch::Contains("expected a finite number > 0"));
    pn::Canvas canvas(4, 4, kWhite);
    CHECK_THROWS_AS(canvas.signed_map(pn::Image(2, 2), 0, 0, 0, 1, limit), pn::Error);
  }
}

TEST_CASE("colour bar: positive end on top, negative at the bottom, white in the middle, labels inside its box") {
  pn::Canvas canvas(120, 120, {200, 200, 200});
  const pn::PixelBox box = canvas.colour_bar(dejavu(), 10, 10, 12, 101, 0.05f, 12, kInk);
  CHECK(canvas.pixel(15, 50 + 10) == pn::kSignedZero);
  const pn::Rgb top = canvas.pixel(15, 10), bottom = canvas.pixel(15, 110);
  CHECK(top[0] > top[2]);
  CHECK(bottom[2] > bottom[0]);
  CHECK(box.x + box.width > 10 + 12 + 4 + dejavu().text_width("\u22120.05", 12) - 1);
  CHECK(changes(canvas, box, {200, 200, 200}).outside == 0);
}

TEST_CASE("canvas lines: a horizontal line covers its pixels and no others, a dashed one leaves gaps, clipped at the edges") {
  pn::Canvas canvas(40, 20, kWhite);
  canvas.line(5, 10, 30, 10, kInk, 1);
  int inked = 0;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x)
      if (canvas.pixel(x, y) == kInk) {
        ++inked;
        CHECK(y == 10);
        CHECK((x >= 5 && x <= 30));
      }
  CHECK(inked == 26);
  pn::Canvas dashed(40, 20, kWhite);
  dashed.line(0, 5, 39, 5, kInk, 1, 4);
  CHECK(dashed.pixel(1, 5) == kInk);   // drawn 0..3
  CHECK(dashed.pixel(5, 5) == kWhite);  // left 4..7
  CHECK(dashed.pixel(9, 5) == kInk);
  pn::Canvas clipped(10, 10, kWhite);
  CHECK_NOTHROW(clipped.line(-50, -50, 60, 60, kInk, 3));
  CHECK(clipped.pixel(5, 5) == kInk);
}
