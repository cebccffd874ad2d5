// docs/modules/backprojection.md's picture: what pnBackprojection computes on a
// shadow map and what it costs, drawn from the GPU's answers.
#include <algorithm>
#include <vector>

#include "figures/figures.h"
#include "fixture_images/texture_fixture.h"
#include "pass_runners/backprojection_pass.h"
#include "pass_runners/minmax_mip_pass.h"

namespace pn {

// The boxes fixture (128², boxes over a sloped ground) under the sun: the map, the visibility of
// a receiver on the ground at every texel (the defaults), and the nodes each one visited (heat,
// square root of the share of the most).
Canvas backprojection_figure(const Context& context, const SourceTree& tree) {
  const int n = 128, scale = 2, gap = 10;
  const auto& boxes = find_fixture("boxes");
  const Image map = generate_fixture(boxes, n, n);
  LightModel sun;  // orthographic: texels 0.004 wide, spread 0.12 (penumbrae up to ~12 texels)
  sun.width = 0.0, sun.spread = 0.12, sun.texel_world = 0.004, sun.near_plane = 0.1, sun.far_plane = 2.0;
  sun.map_size = n;
  const auto map_texture = context.upload(map);  // read beside the chain: it outlives the queries
  const MinMaxMipChain mip = MinMaxMipBuilder(context, tree).build(*map_texture, n);
  std::vector<BackprojectionQuery> queries;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      BackprojectionQuery q;
      q.u = static_cast<float>(x) + 0.5f, q.v = static_cast<float>(y) + 0.5f;
      q.depth = boxes_ground_depth(boxes, static_cast<float>(y), n) + 0.002f;
      q.bias = 0.02f;
      q.tolerance = static_cast<float>(PN_BACKPROJECTION_DEFAULT_TOLERANCE);
      queries.push_back(q);
    }
  const std::vector<BackprojectionResult> results = BackprojectionQueryPass(context, tree).run(mip, sun, queries);
  Image visibility(n, n);
  float most = 1.0f;
  for (int k = 0; k < n * n; ++k) {
    visibility.texels[static_cast<size_t>(k)] = results[static_cast<size_t>(k)].visibility;
    most = std::max(most, results[static_cast<size_t>(k)].nodes);
  }
  const int panel = n * scale;
  Canvas canvas(3 * panel + 4 * gap, panel + 2 * gap, {255, 255, 255});
  canvas.grey(map, 0, gap, gap, scale, 0.2f, 1.0f, {220, 0, 180});
  canvas.grey(visibility, 0, 2 * gap + panel, gap, scale, 0.0f, 1.0f, {220, 0, 180});
  for (int k = 0; k < n * n; ++k) {
    canvas.fill(3 * gap + 2 * panel + (k % n) * scale, gap + (k / n) * scale, scale, scale,
                node_heat(results[static_cast<size_t>(k)].nodes / most));
  }
  return canvas;
}

}  // namespace pn
