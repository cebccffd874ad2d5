#include <iostream>
#include <sstream>

#include "cli/commands.h"
#include "core/bounds.h"
#include "core/error.h"
#include "core/write_file.h"
#include "render/frames_job.h"
#include "render/render_job.h"
#include "technique/technique_registry.h"

namespace pn::cli {

void add_render_command(CLI::App& app, GlobalOptions& global, int& exit_code) {
  auto setup = std::make_shared<RenderSetup>();
  auto techniques = std::make_shared<std::vector<std::string>>();
  auto stages = std::make_shared<bool>(false);
  auto frames = std::make_shared<FramesSetup>();
  auto* cmd = app.add_subcommand("render", "Render a scene with every technique, scored against the ray-traced truth and exact PCSS: PNGs, a labelled sheet, tables");
  auto* scene = cmd->add_option("--scene", setup->scene, "boxes | fence | tall_blocker | city (default boxes); with --frames: moving | moving_city (default moving)");
  cmd->add_option("--model", setup->model, "A mesh file (any format Assimp reads: glTF, OBJ, ...) placed on the ground instead of --scene");
  auto* source = cmd->add_option("--source", setup->source, "Shadow-map source: full | two-map | dirty-rect (default full; with --frames dirty-rect)");
  auto* frame_count = cmd->add_option("--frames", frames->frames, "Render this many frames of an animated scene with one technique (--techniques, default fast): a lit image and a shadow map with the changed rectangles a frame, and the timing table");
  auto* k = cmd->add_option("--k", frames->k, "With --frames: share K of moving triangles, 0..1 (default 0.3)");
  auto* light_scale = cmd->add_option("--light-scale", setup->light_scale, "Multiply the scene's light width by this (default 1): wider penumbrae");
  cmd->add_option("--map-size", setup->map_size, "Shadow-map size N (default 512; on cascades, each cascade's)");
  auto* cascades = cmd->add_option("--cascades", setup->cascades, "A scene lit by the sun (city): its cascades, 1 to 4 (default 3; 0: one map over the whole scene)");
  cmd->add_option("--screen", setup->screen_size, "Screen size (default 512)");
  auto* truth_samples = cmd->add_option("--truth-samples", setup->truth_samples, "Ray-traced truth: S for S x S light samples per pixel (default 16)");
  auto* repeats = cmd->add_option("--repeats", setup->repeats, "Timed runs per technique, median reported (default 3)");
  cmd->add_option("--techniques", *techniques, "Techniques (default exact,poisson,hqepcss,fast; any registry entry, with :key=value overrides)")
      ->delimiter(',');
  auto* stages_flag = cmd->add_flag("--stages", *stages, "Also print each technique's per-stage GPU times");
  cmd->add_option("--out", setup->out, "Directory for the PNG files (default render)");
  cmd->add_option("--glsl-root", global.glsl_root, "Render with the modules in this directory");
  cmd->add_option("--backend", global.backend, "egl-device | egl-surfaceless | osmesa (default: first that works)");
  add_api_option(*cmd, global);
  // Options of the plain render that --frames does not read (issue 26 B18), and --frames's own.
  const std::vector<CLI::Option*> not_with_frames{light_scale, cascades, truth_samples, repeats, stages_flag};
  cmd->callback([setup, techniques, stages, frames, scene, source, frame_count, k, cascades, not_with_frames, &global,
                 &exit_code] {
    if (frame_count->count() > 0) {
      for (const CLI::Option* option : not_with_frames)
        if (option->count() > 0) throw Error(option->get_name() + ": render --frames does not use it");
      if (scene->count() > 0) frames->scene = setup->scene;
      if (source->count() > 0) frames->source = setup->source;
      if (techniques->size() > 1) throw Error("render --frames: expected one technique, got " + std::to_string(techniques->size()));
      if (techniques->size() == 1) frames->technique = parse_technique(techniques->front());
      frames->model = setup->model;
      frames->map_size = setup->map_size;
      frames->screen_size = setup->screen_size;
      frames->out = setup->out;
      validate_frames_setup(*frames);  // before looking for a GL context
      const Api api = chosen_api(global);
      // An --out that cannot be made or written, or a name there that cannot be (issue 39 C8): before any GL work.
      MadeDirectories made(prepare_output_directory(frames->out, frames_output_names(*frames)));
      const SourceTree tree(glsl_root_or_default(global));
      const auto context = create_context(chosen_backend(global), api);
      std::cout << "backend " << backend_name(context->backend()) << ": " << context->renderer() << "\n";
      const FramesResult result = run_frames(*context, tree, *frames);
      made.keep();
      print_frames_table(std::cout, *frames, result);
      std::cout << "wrote " << result.written.size() << " files into " << frames->out.string() << "\n";
      exit_code = 0;
      return;
    }
    if (k->count() > 0) throw Error("--k: render uses it only with --frames (the animated scene's moving share)");
    if (!techniques->empty()) require_list_length("techniques", techniques->size());
    for (const std::string& technique : *techniques) setup->techniques.push_back(parse_technique(technique));
    validate_render_setup(*setup);  // bad input is reported before looking for a GL context
    const Api api = chosen_api(global);  // an unknown API likewise
    const Scene scene = load_render_scene(*setup);  // and a bad model file before anything is written
    if (cascades->count() > 0 && !scene.sun)
      throw Error("--cascades: scene '" + scene.name + "' is not lit by the sun; only the city has cascades");
    // Made, writable, every name legal; removed again if the run fails before writing into it (issue 39 C19).
    MadeDirectories made(prepare_output_directory(setup->out, render_output_names(*setup, scene)));
    const SourceTree tree(glsl_root_or_default(global));
    const auto context = create_context(chosen_backend(global), api);
    std::cout << "backend " << backend_name(context->backend()) << ": " << context->renderer()
              << (api == Api::gl450 ? "" : std::string(", ") + context->version()) << "\n";
    const RenderResult result = run_render(*context, tree, *setup, scene);
    made.keep();
    print_render_table(std::cout, *setup, result, *stages);
    for (const auto& path : result.written) std::cout << "wrote " << path.string() << "\n";
    exit_code = 0;
  });
}

}  // namespace pn::cli
