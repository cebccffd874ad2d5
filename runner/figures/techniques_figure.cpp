// Every technique of render's default sheet (the registry's `rendered` entries) on the boxes
// scene, lit (albedo, N·L and the visibility, as render's sheet): a technique added to the registry is drawn here with no line of its own.
#include <memory>

#include "core/image.h"
#include "draw/font.h"
#include "figures/figures.h"
#include "metrics/lit_image.h"
#include "scene/scene.h"
#include "technique/comparison.h"
#include "technique/technique_registry.h"

namespace pn {

Canvas techniques_figure(const Context& context, const SourceTree& tree) {
  const int n = 128, scale = 2, gap = 8, label = 18, panel = n * scale;
  const Scene scene = make_scene(find_scene_fixture("boxes"), n);
  std::vector<std::unique_ptr<TechniqueConfig>> configs;
  ComparisonSetup setup;
  setup.screen_size = n, setup.repeats = 1, setup.truth_samples = 4;
  for (const std::string& t : render_techniques()) {
    configs.push_back(parse_technique(t));
    setup.techniques.push_back(configs.back().get());
  }
  const Comparison c = compare_techniques(context, tree, scene, setup);
  const Font font;
  const Rgb ink{40, 40, 40};
  const int columns = 1 + static_cast<int>(c.results.size());
  Canvas canvas(columns * (panel + gap) + gap, panel + label + 2 * gap, {255, 255, 255});
  for (int i = 0; i < columns; ++i) {
    const int x = gap + i * (panel + gap);
    const TechniqueResult* r = i == 0 ? nullptr : &c.results[static_cast<size_t>(i - 1)];
    canvas.text(font, x, gap, r ? r->name : "truth (ray traced)", 13, ink);
    canvas.rgb(flip_rows(compose_lit_image(c.surface, r ? r->visibility : c.truth)), x, gap + label, scale);
  }
  return canvas;
}

}  // namespace pn
