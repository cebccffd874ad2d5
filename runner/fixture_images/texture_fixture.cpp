#include "fixture_images/texture_fixture.h"

#include <algorithm>
#include <limits>

#include "core/error.h"
#include "core/integer_hash.h"
#include "core/named.h"

namespace pn {
namespace {

constexpr auto hash32 = integer_hash;

std::uint32_t texel_hash(std::uint32_t seed, int x, int y) {
  return hash32(seed ^ hash32(static_cast<std::uint32_t>(x) ^ hash32(static_cast<std::uint32_t>(y) + 0x9e3779b9U)));
}

// 24 high bits → [0, 1) exactly representable in float.
float unit_float(std::uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }

float texel(const fixtures::TextureFixture& f, int x, int y, int w, int h) {
  using fixtures::Pattern;
  switch (f.pattern) {
    case Pattern::constant: return f.a;
    case Pattern::ramp: {
      const int span = w + h - 2;
      return span == 0 ? f.a : f.a + (f.b - f.a) * static_cast<float>(x + y) / static_cast<float>(span);
    }
    case Pattern::step_edge: return x < w / 2 ? f.a : f.b;
    case Pattern::checker: return ((x / f.cell + y / f.cell) % 2 == 0) ? f.a : f.b;
    case Pattern::impulse: return (x == w / 2 && y == h / 2) ? f.b : f.a;
    case Pattern::noise: return f.a + (f.b - f.a) * unit_float(texel_hash(f.seed, x, y));
    case Pattern::boxes: {
      float depth = boxes_ground_depth(f, static_cast<float>(y), h);
      // Box k: corner and size from hashes of (seed, k), in fractions of the map.
      for (int k = 0; k < f.cell; ++k) {
        const float fx = unit_float(texel_hash(f.seed, k, 0)), fy = unit_float(texel_hash(f.seed, k, 1));
        const float fw = 0.05f + 0.2f * unit_float(texel_hash(f.seed, k, 2));
        const float fh = 0.05f + 0.2f * unit_float(texel_hash(f.seed, k, 3));
        const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(w);
        const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(h);
        if (u >= fx && u < fx + fw && v >= fy && v < fy + fh)
          depth = std::min(depth, f.a + 0.25f * (f.b - f.a) * unit_float(texel_hash(f.seed, k, 4)));
      }
      return depth;
    }
    case Pattern::nonfinite: {
      const std::uint32_t hv = texel_hash(f.seed, x, y);
      switch (hv & 31U) {
        case 0: case 1: return std::numeric_limits<float>::quiet_NaN();
        case 2: return std::numeric_limits<float>::infinity();
        case 3: return -std::numeric_limits<float>::infinity();
        default: return f.a + (f.b - f.a) * unit_float(hv);
      }
    }
  }
  return 0.0f;
}

}  // namespace

float boxes_ground_depth(const fixtures::TextureFixture& boxes, float y, int height) {
  const float span = boxes.b - boxes.a;
  return boxes.b - 0.5f * span * (height > 1 ? y / static_cast<float>(height - 1) : 0.0f);
}

Image generate_fixture(const fixtures::TextureFixture& fixture, int width, int height) {
  if (width < 1 || height < 1)
    throw Error("fixture '" + std::string(fixture.name) + "' size " + std::to_string(width) + "x" +
                std::to_string(height) + ": expected at least 1x1");
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.at(x, y) = texel(fixture, x, y, width, height);
  return image;
}

const fixtures::TextureFixture& find_fixture(const std::string& name) {
  return find_named(fixtures::kTextureFixtures, name, "fixture '" + name + "'");
}

Image generate_two_occluders(const fixtures::TwoOccluderFixture& f) {
  Image map(f.size, f.size, 1, f.plane_depth);
  const auto inside = [](int v, int lo, int hi) { return v >= lo && v < hi; };
  for (int y = 0; y < f.size; ++y)
    for (int x = 0; x < f.size; ++x) {
      if (inside(x, f.far_lo, f.far_hi) && inside(y, f.far_lo, f.far_hi)) map.at(x, y) = f.far_depth;
      if (inside(x, f.near_lo, f.near_hi) && inside(y, f.near_lo, f.near_hi)) map.at(x, y) = f.near_depth;
    }
  return map;
}

}  // namespace pn
