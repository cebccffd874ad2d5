// Light bleeding on the two-occluder map (docs/modules/vsm.md): the map, the
// exact Gaussian PCF visibility over the blur's window (CPU brute force), and
// what vsm.glsl computes on the GPU for receivers on the plane behind both
// occluders — VSM's Chebyshev bound alone, with the bleeding reduction, with
// the reduction and the depth-range bound, and EVSM-4 with both — above their
// signed error against the exact PCF (red: light that bleeds).
#include <string>
#include <vector>

#include "figures/bleeding_panels.h"
#include "figures/figures.h"
#include "fixture_images/texture_fixture.h"
#include "gl/query_device_gl.h"
#include "gl/texture.h"
#include "pass_runners/depth_pyramid_pass.h"
#include "pass_runners/vsm_pass.h"
#include "reference/vsm_reference.h"

namespace pn {
namespace {

// Channel `c` of the query (0 visibility, 1 Chebyshev bound, 2 reduced) for every texel's receiver on the plane.
Image plane_visibility(const Context& context, const SourceTree& tree, const Image& map, const VsmParams& params,
                       int c) {
  const auto& f = fixtures::kTwoOccluders;
  const int n = map.width;
  const GlObject texture = upload_float_texture(context, map);
  const VsmMomentsPass moments(context, tree);
  const VsmMoments blurred = moments.blurred(moments.moments(GlDeviceTexture(texture), n, n, params), params);
  const DepthPyramid pyramid = DepthPyramidBuilder(context, tree).build(GlDeviceTexture(texture), n, n, 30);
  std::vector<VsmQuery> queries;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) queries.push_back({x, y, f.plane_depth, f.bias});
  const std::vector<Query> results = VsmQueryPass(context, tree).run(blurred, pyramid, queries, params);
  Image out(n, n);
  for (size_t k = 0; k < results.size(); ++k) out.texels[k] = results[k][static_cast<size_t>(c)];
  return out;
}

}  // namespace

Canvas vsm_bleeding_figure(const Context& context, const SourceTree& tree) {
  const auto& f = fixtures::kTwoOccluders;
  const int n = f.size;
  const Image map = generate_two_occluders(f);
  VsmParams vsm;
  vsm.near_depth = 0.0f;
  vsm.far_depth = 1.0f;
  VsmParams evsm = vsm;
  evsm.kind = VsmKind::evsm4;
  Image exact(n, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) exact.at(x, y) = static_cast<float>(gaussian_pcf_visibility(map, x, y, f.plane_depth - f.bias, vsm.blur));
  return bleeding_panels(map, exact, "exact PCF",
                         {{"VSM: Chebyshev alone", plane_visibility(context, tree, map, vsm, 1), ""},
                          {"+ linstep(0.2, 1, p)", plane_visibility(context, tree, map, vsm, 2), ""},
                          {"+ depth-range bound", plane_visibility(context, tree, map, vsm, 0), ""},
                          {"EVSM-4 (40, 5), both", plane_visibility(context, tree, map, evsm, 0), ""}});
}

}  // namespace pn
