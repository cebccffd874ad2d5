// Light bleeding of summed-area variance soft shadows on the two-occluder map
// (docs/modules/savsm.md): the map, the exact PCF visibility over the filter
// square savsm.glsl chose for every receiver on the plane behind both
// occluders (CPU brute force), and what the module computes on the GPU over
// the same squares — Chebyshev's bound alone, with the bleeding reduction,
// and with the reduction and the depth-range bound — above their signed error
// against the exact PCF (red: light that bleeds), with the mean excess light.
#include <string>
#include <vector>

#include "core/format.h"
#include "figures/bleeding_panels.h"
#include "figures/figures.h"
#include "fixture_images/texture_fixture.h"
#include "gl/query_device_gl.h"
#include "gl/texture.h"
#include "pass_runners/minmax_mip_pass.h"
#include "pass_runners/savsm_pass.h"
#include "pass_runners/summed_area_pass.h"
#include "reference/savsm_reference.h"

namespace pn {
namespace {

// The light over the fixture's depths 0.3 / 0.6 / 0.9: a search square that covers the map and
// penumbrae of about 20 texels behind the near occluder.
LightModel two_occluder_light(int n) {
  LightModel light;
  light.width = 0.15;
  light.near_plane = 0.1;
  light.far_plane = 1.2;
  light.fov_radians = 1.0;
  light.map_size = n;
  return light;
}

}  // namespace

Canvas savsm_bleeding_figure(const Context& context, const SourceTree& tree) {
  const auto& f = fixtures::kTwoOccluders;
  const int n = f.size;
  const Image map = generate_two_occluders(f);
  const LightModel light = two_occluder_light(n);
  const GlObject texture = upload_float_texture(context, map);
  const MomentsTable table = SummedAreaMomentsPass(context, tree).build(GlDeviceTexture(texture), n, n, MomentsTableKind::fixed,
                                                                        unit_range(light.near_plane, light.far_plane));
  const GlDeviceTexture map_texture(texture);  // the chain's map: kept while the chain is
  const MinMaxMipChain mip = MinMaxMipBuilder(context, tree).build(map_texture, n);
  const SavsmQueryPass pass(context, tree);
  std::vector<SavsmReceiver> receivers;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) receivers.push_back({x + 0.5f, y + 0.5f, f.plane_depth});
  SavsmSettings raw, reduced, bounded;
  raw.bias = reduced.bias = bounded.bias = f.bias;
  raw.bleeding_reduction = 0.0f;
  raw.bound = reduced.bound = false;
  constexpr int kShown = 3;
  const SavsmSettings settings[kShown] = {raw, reduced, bounded};
  Image shown[kShown] = {Image(n, n), Image(n, n), Image(n, n)};
  Image exact(n, n);
  double excess[kShown] = {0, 0, 0};
  for (int i = 0; i < kShown; ++i) {
    const std::vector<SavsmQueryResult> r = pass.query(table, *mip.texture, receivers, light, settings[i]);
    for (size_t k = 0; k < r.size(); ++k) {
      shown[i].texels[k] = r[k].visibility;
      if (i == 0) {  // the same squares in every setting (the min blocker): exact PCF over them
        exact.texels[k] = static_cast<float>(savsm_pcf_visibility(map, r[k].filter, f.plane_depth - f.bias));
      }
      excess[i] += std::max(0.0f, shown[i].texels[k] - exact.texels[k]) / static_cast<double>(r.size());
    }
  }
  const char* names[kShown] = {"SAVSM: Chebyshev alone", "+ linstep(0.2, 1, p)", "+ depth-range bound"};
  std::vector<BleedingPanel> panels;
  for (int i = 0; i < kShown; ++i)
    panels.push_back({names[i], shown[i], "mean excess " + format_number("%.4f", excess[i])});
  return bleeding_panels(map, exact, "exact PCF, same squares", panels);
}

}  // namespace pn
