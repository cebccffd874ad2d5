// Cases of the reuse check: on seeded region maps (smooth fields with steps,
// zeros and NaN entries) of several sizes, for tiles 1 (no reuse), 2, 4, 8 and several
// sigmas, and the largest tile, 16, with chains as long as its walk's bound, the GPU's parent
// codes, representatives and gathered values equal
// the CPU reference (explicit parent pointers and root finding) exactly, and
// no group crosses a tile. The fraction of representatives is in each name.
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "check/module_check.h"
#include "core/format.h"
#include "core/seeded_random.h"
#include "pass_runners/reuse_pass.h"
#include "reference/reuse_reference.h"
#include "reuse.h"  // glsl/reuse.h: the parent codes PN_REUSE_*

namespace pn {
namespace {

// A search-region-like map: depth, centre and side vary smoothly in steps, so
// neighbours are often, but not always, similar; a few zeros and NaNs.
Image region_map(int w, int h, std::uint32_t seed) {
  SeededRandom random(seed);
  Image e(w, h, 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float d = 0.5f + 0.3f * std::sin(x / 11.0f) * std::cos(y / 7.0f);
      e.at(x, y, 0) = std::round(d * 40.0f) / 40.0f + (random.uniform_int(0, 15) == 0 ? 0.2f : 0.0f);
      e.at(x, y, 1) = std::floor((x + 0.5f) * 3.0f / 4.0f) + 0.5f;
      e.at(x, y, 2) = std::floor((y + 0.5f) * 3.0f / 4.0f) + 0.5f;
      e.at(x, y, 3) = std::exp2(std::round(3.0f + 2.0f * std::sin((x + y) / 23.0f)));
      const int special = random.uniform_int(0, 99);
      if (special == 0) e.at(x, y, 0) = std::numeric_limits<float>::quiet_NaN();
      if (special == 1) e.at(x, y, 3) = 0.0f;
    }
  return e;
}

}  // namespace

std::vector<CaseResult> run_reuse_check(const CheckEnvironment& env) {
  const ReusePass pass(env.device, env.tree);
  const Tolerance exact = Tolerance::exact();
  std::vector<CaseResult> results;
  struct Size { int w, h; };
  std::uint32_t seed = 0x5eed0010u;
  for (Size size : {Size{1, 1}, Size{64, 64}, Size{100, 37}, Size{256, 256}}) {
    const Image entries = region_map(size.w, size.h, seed++);
    Image values(size.w, size.h);
    SeededRandom random(seed++);
    for (float& v : values.texels) v = random.uniform_float(0.0f, 1.0f);
    const std::unique_ptr<DeviceTexture> entry_texture = env.device.upload(entries);
    const std::unique_ptr<DeviceTexture> value_texture = env.device.upload(values);
    for (ReuseParams params : {ReuseParams{0.0f, 0.1f, 0.1f, 4}, ReuseParams{0.0f, 0.1f, 0.1f, 2},
                               ReuseParams{0.0f, 0.1f, 0.1f, 8}, ReuseParams{0.0f, 0.1f, 0.1f, 1},
                               ReuseParams{0.0f, 0.0f, 0.0f, 4},
                               ReuseParams{0.5f, 0.3f, 0.3f, 4},
                               // The largest tile, every finite neighbour similar (sigma 1 holds any two
                               // non-negative values): chains of 2 (k - 1) = 30 links, every step the
                               // walk's bound allows, from a tile's far corner.
                               ReuseParams{1.0f, 1.0f, 1.0f, PN_REUSE_MAX_TILE}}) {
      const std::unique_ptr<DeviceTexture> parents = pass.link(*entry_texture, size.w, size.h, params);
      const std::unique_ptr<DeviceTexture> gathered = pass.gather(*parents, *value_texture, size.w, size.h, params.tile);
      const Image observed_parents = env.device.read_texture(*parents);
      const Image observed = env.device.read_texture(*gathered);

      const std::vector<int> parent = reuse_parents(entries, params);
      const std::vector<int> root = reuse_roots(parent);
      Image expected_parents(size.w, size.h), expected(size.w, size.h, 4), same_tile(size.w, size.h, 1, 1.0f),
          observed_same_tile(size.w, size.h);
      int representatives = 0;
      for (int y = 0; y < size.h; ++y)
        for (int x = 0; x < size.w; ++x) {
          const int i = y * size.w + x, p = parent[static_cast<size_t>(i)], r = root[static_cast<size_t>(i)];
          const int code = p < 0 ? PN_REUSE_NONE : p == i - 1 ? PN_REUSE_LEFT : PN_REUSE_TOP;
          expected_parents.at(x, y) = static_cast<float>(code);
          expected.at(x, y, 0) = static_cast<float>(r % size.w);
          expected.at(x, y, 1) = static_cast<float>(r / size.w);
          expected.at(x, y, 2) = values.at(r % size.w, r / size.w);
          representatives += p < 0;
          const int rx = static_cast<int>(observed.at(x, y, 0)), ry = static_cast<int>(observed.at(x, y, 1));
          observed_same_tile.at(x, y) = (rx / params.tile == x / params.tile && ry / params.tile == y / params.tile) ? 1.0f : 0.0f;
        }
      const std::string name = std::to_string(size.w) + "x" + std::to_string(size.h) + " k=" +
                                std::to_string(params.tile) + " sigma " + format_number("%g", params.sigma1) + "/" +
                                format_number("%g", params.sigma2) + "/" + format_number("%g", params.sigma3) +
                                " (representatives " +
                                format_number("%.3f", double(representatives) / (double(size.w) * size.h)) + ")";
      results.push_back({name + ": parent codes", exact, compare(expected_parents, observed_parents, exact)});
      results.push_back({name + ": representative and its value at every pixel", exact,
                         compare(channels_of(expected, 0, 3), channels_of(observed, 0, 3), exact)});
      results.push_back({name + ": no group crosses a tile", exact, compare(same_tile, observed_same_tile, exact)});
    }
    // Tile 1 over links made for tile 2: a group is one pixel whatever the links say (the walk
    // takes 2 (k - 1) = 0 steps), so every pixel is its own representative.
    const std::unique_ptr<DeviceTexture> pairs = pass.link(*entry_texture, size.w, size.h, ReuseParams{0.0f, 0.1f, 0.1f, 2});
    const Image alone = env.device.read_texture(*pass.gather(*pairs, *value_texture, size.w, size.h, 1));
    Image own(size.w, size.h, 3);
    for (int y = 0; y < size.h; ++y)
      for (int x = 0; x < size.w; ++x) own.at(x, y, 0) = float(x), own.at(x, y, 1) = float(y), own.at(x, y, 2) = values.at(x, y);
    results.push_back({std::to_string(size.w) + "x" + std::to_string(size.h) +
                           " k=1 over k=2 links: every pixel its own representative", exact,
                       compare(own, channels_of(alone, 0, 3), exact)});
  }
  return results;
}

}  // namespace pn
