#include "render/frames_job.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "core/error.h"
#include "core/format.h"
#include "core/write_file.h"
#include "draw/canvas.h"
#include "metrics/lit_image.h"
#include "gl/gpu_timer.h"
#include "gl/texture.h"
#include "pass_runners/gbuffer_pass.h"
#include "pass_runners/surface_pass.h"
#include "render/render_job.h"
#include "scene/animated_scene.h"
#include "technique/shadow_map_sources.h"
#include "technique/technique_registry.h"

namespace pn {
namespace {

constexpr const char* kDefaultTechnique = "fast";
// The map picture's grey scale: light depth 10 (black) to 21 (white, the ground at 20); +Inf white.
constexpr float kDepthBlack = 10.0f, kDepthWhite = 21.0f;
constexpr Rgb kChanged{220, 30, 30};

std::string frame_stem(const std::string& scene, int f) {
  char name[32];
  std::snprintf(name, sizeof name, "_frame_%04d", f);
  return scene + name;
}

}  // namespace

void validate_frames_setup(const FramesSetup& s) {
  find_animated_scene_fixture(s.scene);
  validate_moving_share(s.k, "K");
  if (s.frames < 1 || s.frames > 1000) throw Error("frames " + std::to_string(s.frames) + ": expected 1..1000");
  find_shadow_map_source(s.source);
  if (s.map_size < 16 || s.map_size > 4096) throw Error("shadow-map size " + std::to_string(s.map_size) + ": expected 16..4096");
  if (s.screen_size < 16 || s.screen_size > 4096) throw Error("screen size " + std::to_string(s.screen_size) + ": expected 16..4096");
  if (s.technique) s.technique->validate();
  validate_animated_scene_model(s.model);  // last: it reads the file
}

std::vector<std::string> frames_output_names(const FramesSetup& setup) {
  const std::string scene = find_animated_scene_fixture(setup.scene).name;
  std::vector<std::string> names;
  for (int f = 0; f < setup.frames; ++f) {
    names.push_back(frame_stem(scene, f) + ".png");
    names.push_back(frame_stem(scene, f) + "_map.png");
  }
  names.push_back(scene + "_frames.tsv");
  return names;
}

FramesResult run_frames(const Context& context, const SourceTree& tree, const FramesSetup& setup) {
  validate_frames_setup(setup);
  AnimatedScene animation(find_animated_scene_fixture(setup.scene), setup.k, setup.map_size, animated_scene_model(setup.model));
  SourceOptions options;
  options.mip_chain = true;  // Fast PCSS's structure, kept by the source
  const auto source = find_shadow_map_source(setup.source).make(context, tree, options);
  TechniqueResources resources(context, tree);
  const std::shared_ptr<const TechniqueConfig> config =
      setup.technique ? setup.technique : std::shared_ptr<const TechniqueConfig>(parse_technique(kDefaultTechnique));
  const std::unique_ptr<Technique> technique = config->create(resources);
  const SecondLayerRenderers layers(context, tree, second_layers_of({config.get()}));
  const GBufferRenderer gbuffers(context, tree);
  const SurfaceRenderer surfaces(context, tree);
  const int n = setup.map_size, size = setup.screen_size;

  create_output_directory(setup.out);
  FramesResult result;
  result.technique = config->name();
  std::ostringstream table;
  table << "frame\tmoving\tmap_ms\ttechnique_ms\tchanged\n";
  for (int f = 0; f < setup.frames; ++f) {
    const Scene scene = animation.frame(f);
    result.scene_name = scene.name;
    StageClock clock(context);
    clock.start();
    const SourcedMap& sourced = source->render(scene);
    clock.stage("shadow map");
    FrameRow row;
    row.frame = f;
    row.map_ms = clock.read().front().second;
    row.moving_share = animation.moving_share(f);
    row.changed_share = map_share(sourced.changed, n);
    const std::unique_ptr<DeviceTexture> gbuffer =
        gbuffers.render_texture(scene, size, fixtures::kNormalOffsetTexels, scene.map_light());
    TechniqueInputs inputs{scene.light, size, sourced.map, gbuffer.get(), sourced.mip, sourced.pyramid};
    const SecondLayerTextures second_layers = layers.render(scene, scene.map_light(), *sourced.map);
    inputs.second_layers = second_layers.view();
    const TechniqueFrame frame = technique->run(inputs, false);
    row.technique_ms = frame.total_ms();
    result.rows.push_back(row);
    table << f << "\t" << format_number("%.4f", row.moving_share) << "\t" << format_ms(row.map_ms) << "\t"
          << format_ms(row.technique_ms) << "\t" << format_number("%.4f", row.changed_share) << "\n";

    const Image visibility = context.read_texture(*frame.visibility, 0, 0);
    const Image surface = read_float_texture(context, surfaces.render(scene, size));
    const std::filesystem::path lit = setup.out / (frame_stem(scene.name, f) + ".png");
    Canvas picture(size, size, {0, 0, 0});
    picture.rgb(flip_rows(compose_lit_image(surface, visibility)), 0, 0, 1);
    picture.write_png(lit);
    result.written.push_back(lit);

    const Image map = context.read_texture(*sourced.map, 0, 0);
    Canvas overlay(n, n, {255, 255, 255});
    overlay.grey(flip_rows(map), 0, 0, 0, 1, kDepthBlack, kDepthWhite, {255, 255, 255});
    for (const TexelRect& r : sourced.changed)  // rows from the map's bottom, the picture's from its top
      if (!r.empty()) overlay.outline(r.x0, n - r.y1, r.x1 - r.x0, r.y1 - r.y0, kChanged, std::max(1, n / 512));
    const std::filesystem::path map_path = setup.out / (frame_stem(scene.name, f) + "_map.png");
    overlay.write_png(map_path);
    result.written.push_back(map_path);
  }
  const std::filesystem::path tsv = setup.out / (result.scene_name + "_frames.tsv");
  write_file_atomically(tsv, table.str());
  result.written.push_back(tsv);
  return result;
}

void print_frames_table(std::ostream& out, const FramesSetup& setup, const FramesResult& result) {
  out << "scene " << result.scene_name << ", K = " << format_number("%g", setup.k) << ", " << setup.frames
      << " frames, source " << setup.source << ", shadow map " << setup.map_size << "², " << result.technique << " at "
      << setup.screen_size << "²; GPU ms\n";
  out << "frame   moving    map ms   " << result.technique << " ms   changed\n";
  for (const FrameRow& r : result.rows)
    out << format_number("%5.0f", r.frame) << format_number("%9.3f", r.moving_share) << format_number("%10.2f", r.map_ms)
        << format_number("%12.2f", r.technique_ms) << format_number("%9.1f", 100.0 * r.changed_share) << "%\n";
}

}  // namespace pn
