// The pipeline's stages on the boxes scene (docs/pipeline.md): one panel per
// stage, each read back from the GPU frame of Fast PCSS with the paper's defaults.
#include <algorithm>
#include <cmath>

#include "cache/full_render_source.h"
#include "draw/canvas.h"
#include "figures/figures.h"
#include "gl/texture.h"
#include "pipeline/pcss_pipeline.h"
#include "frame/scene_frame.h"
#include "scene/scene.h"

namespace pn {

Canvas pipeline_stages_figure(const Context& context, const SourceTree& tree) {
  const int n = 256, gap = 6;
  const Scene scene = make_scene(fixtures::kScenes[0], n);
  const PcssPipeline pipeline(context, tree);
  FullRenderSource source(context, tree);
  const SceneFrame scene_frame = render_scene_frame(context, source, GBufferRenderer(context, tree), scene, n);
  PcssSettings fast = fast_pcss();
  fast.staged = true;  // the steps' own maps, drawn one by one
  const PcssFrame frame = pipeline.run(scene_frame.inputs(), fast);
  const auto read = [&](const DeviceTexture& t) { return flip_rows(context.read_texture(t, 0, 0)); };
  const Image map = read(*scene_frame.shadow_map), gbuffer = read(*scene_frame.gbuffer);
  const Image search = read(*frame.search_map), filter = read(*frame.filter_map);
  // Region sides on a log scale from 1 to 64 texels; lit entries (s < 0) white.
  const auto sides = [&](const Image& entries) {
    Image out(n, n, 1, 1.0f);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        if (entries.at(x, y, 3) >= 0.0f)
          out.at(x, y) = std::clamp(std::log2(std::max(entries.at(x, y, 3), 1.0f)) / 6.0f, 0.0f, 0.85f);
    return out;
  };
  Canvas canvas(6 * n + 5 * gap, n, {255, 255, 255});
  canvas.grey(map, 0, 0, 0, 1, 10.0f, 20.0f, {255, 255, 255});                // 1: light depth 10..20
  canvas.grey(gbuffer, 2, n + gap, 0, 1, 10.0f, 20.0f, {255, 255, 255});      // 2: receivers' light depth
  canvas.grey(sides(search), 0, 2 * (n + gap), 0, 1, 0.0f, 1.0f, {255, 0, 255});  // 3: search side
  canvas.grey(sides(filter), 0, 3 * (n + gap), 0, 1, 0.0f, 1.0f, {255, 0, 255});  // 4: filter side
  canvas.grey(read(*frame.visibility), 0, 4 * (n + gap), 0, 1, 0.0f, 1.0f, {255, 0, 255});  // 5
  canvas.grey(read(frame.soft_shadow()), 0, 5 * (n + gap), 0, 1, 0.0f, 1.0f, {255, 0, 255});  // 6
  return canvas;
}

}  // namespace pn
