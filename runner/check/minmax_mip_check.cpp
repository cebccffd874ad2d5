// Cases of the minmax_mip check: every level of glsl/minmax_mip.glsl's aligned
// min / max chain (node levels 2 to log2 P: below, the map itself), built on the GPU for every
// fixture at N = 2, 3, 37, 64, 300 and 512, against the definition — per aligned node, the min and max of the
// sanitized depths of its texels that lie in the map, (+Inf, -Inf) for a node
// wholly in the padding up to the power of two — read back two nodes a texel,
// bit-exact (min and max round nothing).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "check/module_check.h"
#include "fixture_images/texture_fixture.h"
#include "pass_runners/minmax_mip_pass.h"
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

}  // namespace

std::vector<CaseResult> run_minmax_mip_check(const CheckEnvironment& env) {
  const MinMaxMipBuilder builder(env.device, env.tree);
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
    }
  return results;
}

}  // namespace pn
