// Cases of the minmax_mip check: every level of glsl/minmax_mip.glsl's aligned
// min / max chain (node levels 2 to log2 P: below, the map itself), built on the GPU for every
// fixture at N = 2, 3, 37, 64, 300 and 512, against the definition — per aligned node, the min and max of the
// sanitized depths of its texels that lie in the map, (+Inf, -Inf) for a node
// wholly in the padding up to the power of two — read back two nodes a texel,
// bit-exact (min and max round nothing). On each chain the reads a caller makes: pnMipSquareMinMax
// over squares anywhere about the map (sides 0..2N, origins off its edges too) against the min and
// max of the sanitized depths over the aligned nodes of level max(ceil(log2 s) - 1, 2) that touch
// the square clipped to the map (s its longer side; (+Inf, -Inf) when empty), and pnMipCombineTexel at every level's texels
// — at or below the first level too, which read as the level above — against the definition's
// level; bit-exact.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "check/module_check.h"
#include "fixture_images/texture_fixture.h"
#include "core/seeded_random.h"
#include "pass_runners/minmax_mip_pass.h"
#include "pass_runners/minmax_mip_query_pass.h"
#include "reference/depth_pyramid_reference.h"

namespace pn {
namespace {

constexpr int kSizes[] = {2, 3, 37, 64, 300, 512};

// Level `level` as the module defines it, laid out as the texture holds it: texel (c, r) = nodes 2c and 2c + 1 of row r.
Image expected_level(const Image& depth, int padded, int level) {
  const int rows = padded >> level, width = std::max(rows / 2, 1), side = 1 << level;
  const float inf = std::numeric_limits<float>::infinity();
  Image out(width, rows, 4);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < 2 * width; ++c) {
      float lo = inf, hi = -inf;
      if (c < rows)  // the top level's second half is not a node
        for (int y = r * side; y < std::min((r + 1) * side, depth.height); ++y)
          for (int x = c * side; x < std::min((c + 1) * side, depth.width); ++x)
            lo = std::min(lo, depth.at(x, y)), hi = std::max(hi, depth.at(x, y));
      out.at(c / 2, r, 2 * (c % 2)) = lo;
      out.at(c / 2, r, 2 * (c % 2) + 1) = hi;
    }
  return out;
}

// pnMipSquareMinMax and pnMipCombineTexel on one built chain against the definition (the file's head).
void add_read_cases(const std::string& name, const MinMaxMipQueryPass& pass, const MinMaxMipChain& chain,
                    const Image& depth, std::vector<CaseResult>& results) {
  const int n = chain.map_size;
  const float inf = std::numeric_limits<float>::infinity();
  SeededRandom random(0x5eed0054u + static_cast<std::uint32_t>(n));
  std::vector<MinMaxMipQuery> queries;
  Image expected_squares(200, 1, 2), expected_combined(200, 1, 4);
  std::vector<Image> levels;
  for (int level = 0; level <= chain.top_level; ++level)
    levels.push_back(level > chain.first_level ? expected_level(depth, chain.padded_size, level) : Image());
  for (int k = 0; k < 200; ++k) {
    MinMaxMipQuery q;
    q.origin_x = static_cast<int>(std::floor(random.uniform_float(-4.0f, n + 4.0f)));
    q.origin_y = static_cast<int>(std::floor(random.uniform_float(-4.0f, n + 4.0f)));
    q.side = k % 10 == 0 ? 0 : static_cast<int>(random.uniform_float(1.0f, 2.0f * n + 1.0f));
    const int x0 = std::clamp(q.origin_x, 0, n), y0 = std::clamp(q.origin_y, 0, n);
    const int x1 = std::clamp(q.origin_x + q.side, x0, n), y1 = std::clamp(q.origin_y + q.side, y0, n);
    // The aligned nodes of level max(ceil(log2 s) - 1, the first), s the clipped square's longer
    // side, that touch it (their texels in the map).
    float lo = inf, hi = -inf;
    if (x1 > x0 && y1 > y0) {
      const int s = std::max(x1 - x0, y1 - y0);
      int level = chain.first_level;
      while ((2 << level) < s) ++level;  // 2^(level + 1) >= s
      level = std::min(level, chain.top_level);
      const int cx0 = x0 >> level << level, cy0 = y0 >> level << level;
      const int cx1 = std::min((((x1 - 1) >> level) + 1) << level, n), cy1 = std::min((((y1 - 1) >> level) + 1) << level, n);
      for (int y = cy0; y < cy1; ++y)
        for (int x = cx0; x < cx1; ++x) lo = std::min(lo, depth.at(x, y)), hi = std::max(hi, depth.at(x, y));
    }
    expected_squares.at(k, 0, 0) = lo, expected_squares.at(k, 0, 1) = hi;
    // Every level from 0 (the levels the map gives read as the first combined one) to the top, where
    // the chain has a combined level (P >= 8).
    q.level = k % (chain.top_level + 1);
    const int read = std::max(q.level, chain.first_level + 1);
    if (read <= chain.top_level) {
      const Image& level = levels[read];
      q.texel_x = std::min(static_cast<int>(random.uniform_float(0.0f, static_cast<float>(level.width))), level.width - 1);
      q.texel_y = std::min(static_cast<int>(random.uniform_float(0.0f, static_cast<float>(level.height))), level.height - 1);
      for (int c = 0; c < 4; ++c) expected_combined.at(k, 0, c) = level.at(q.texel_x, q.texel_y, c);
    }
    queries.push_back(q);
  }
  const std::vector<MinMaxMipQueryResult> observed = pass.run(chain, queries);
  Image squares(200, 1, 2), combined(200, 1, 4);
  for (int k = 0; k < 200; ++k) {
    squares.at(k, 0, 0) = observed[k].min, squares.at(k, 0, 1) = observed[k].max;
    for (int c = 0; c < 4; ++c) combined.at(k, 0, c) = observed[k].combined[c];
  }
  const Tolerance exact = Tolerance::exact();
  results.push_back({name + ": pnMipSquareMinMax over 200 squares (sides 0..2N, origins off the edges) vs the min "
                            "and max over the aligned nodes each touches (query k at (k, 0)[min, max])",
                     exact, compare(expected_squares, squares, exact)});
  if (chain.top_level > chain.first_level)  // a combined level to read (P >= 8)
    results.push_back({name + ": pnMipCombineTexel at every level's texels (the first level and below read as the "
                              "level above) vs the definition's level (query k at (k, 0))",
                       exact, compare(expected_combined, combined, exact)});
}

}  // namespace

std::vector<CaseResult> run_minmax_mip_check(const CheckEnvironment& env) {
  const MinMaxMipBuilder builder(env.device, env.tree);
  const MinMaxMipQueryPass reads(env.device, env.tree);
  std::vector<CaseResult> results;
  const Tolerance exact = Tolerance::exact();
  for (const auto& fixture : check_texture_fixtures(env))
    for (int n : kSizes) {
      const Image map = generate_fixture(fixture, n, n);
      const Image depth = sanitized_depths(map);
      const std::unique_ptr<DeviceTexture> texture = env.device.upload(map);
      const MinMaxMipChain chain = builder.build(*texture, n);
      for (int level = chain.first_level; level <= chain.top_level; ++level) {
        const Image expected = expected_level(depth, chain.padded_size, level);
        const Image observed = read_mip_chain_level(env.device, chain, level);
        results.push_back({std::string(fixture.name) + " " + std::to_string(n) + "x" + std::to_string(n) + " (P = " +
                               std::to_string(chain.padded_size) + ") level " + std::to_string(level) +
                               ": texel (c, r) = (min, max) of nodes 2c, 2c+1",
                           exact, compare(expected, observed, exact)});
      }
      add_read_cases(std::string(fixture.name) + " " + std::to_string(n) + "x" + std::to_string(n), reads, chain, depth,
                     results);
    }
  return results;
}

}  // namespace pn
