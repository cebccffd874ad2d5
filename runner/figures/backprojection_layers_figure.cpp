// docs/modules/backprojection.md's second picture (issue 42): what the second
// layer adds — the tall blocker under its light 4 times as wide, the map and
// its back-face layer seen from the light, and back-projection's error against
// the ray-traced truth without the layer and over slabs.
#include <memory>
#include <string>

#include "draw/font.h"
#include "figures/figures.h"
#include "metrics/lit_image.h"
#include "pass_runners/second_layer_pass.h"
#include "scenes.h"
#include "scene/scene.h"
#include "technique/comparison.h"
#include "technique/technique_registry.h"

namespace pn {

Canvas backprojection_layers_figure(const Context& context, const SourceTree& tree) {
  const int n = 128, scale = 2, gap = 8, label = 18, panel = n * scale;
  Scene scene = make_scene(find_scene_fixture("tall_blocker"), n);
  scale_light_width(scene, 4.0, "light width factor");
  const ShadowMapRenderer maps(context, tree);
  const std::unique_ptr<DeviceTexture> map = maps.render_texture(scene, scene.map_light());
  const SecondLayerTextures layers =
      SecondLayerRenderers(context, tree, {MapLayer::back_faces}).render(scene, scene.map_light(), *map);
  const std::unique_ptr<TechniqueConfig> none = parse_technique("backprojection:layer=none");
  const std::unique_ptr<TechniqueConfig> slabs = parse_technique("backprojection");
  ComparisonSetup setup;
  setup.screen_size = n, setup.repeats = 1, setup.truth_samples = 16;
  setup.techniques = {none.get(), slabs.get()};
  const Comparison c = compare_techniques(context, tree, scene, setup);

  const Font font;
  const Rgb ink{40, 40, 40}, empty{220, 0, 180};
  Canvas canvas(5 * (panel + gap) + gap, panel + label + 2 * gap, {255, 255, 255});
  const auto at = [&](int i) { return gap + i * (panel + gap); };
  const float near = static_cast<float>(fixtures::kLightNear), far = static_cast<float>(fixtures::kLightHeight + 1.0f);
  canvas.text(font, at(0), gap, "the map (light depth)", 13, ink);
  canvas.grey(flip_rows(context.read_texture(*map, 0, 0)), 0, at(0), gap + label, scale, near, far, empty);
  canvas.text(font, at(1), gap, "its back-face layer", 13, ink);
  canvas.grey(flip_rows(context.read_texture(*layers.back_faces, 0, 0)), 0, at(1), gap + label, scale, near, far, empty);
  canvas.text(font, at(2), gap, "truth (ray traced)", 13, ink);
  canvas.rgb(flip_rows(compose_lit_image(c.surface, c.truth)), at(2), gap + label, scale);
  for (int k = 0; k < 2; ++k) {
    const TechniqueResult& r = c.results[static_cast<size_t>(k)];
    Image error = r.visibility;
    for (size_t i = 0; i < error.texels.size(); ++i) error.texels[i] -= c.truth.texels[i];
    canvas.text(font, at(3 + k), gap, (k == 0 ? "error, no layer" : "error, over slabs"), 13, ink);
    canvas.signed_map(flip_rows(error), 0, at(3 + k), gap + label, scale, 0.5f);
  }
  return canvas;
}

}  // namespace pn
