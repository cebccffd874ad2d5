// `penumbra render`, the project's main job: one scene — a box scene or a
// model from a mesh file — rendered by every technique in the same run
// through the technique seam, each scored against the ray-traced truth and
// against exact PCSS (metrics/scores.h); per technique its soft-shadow map, lit
// image and error against the truth as PNG, a labelled sheet, and a table.
#pragma once

#include <filesystem>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "gl/context.h"
#include "scene/scene.h"
#include "shader/source_tree.h"
#include "technique/comparison.h"
#include "frame/technique.h"

namespace pn {

struct RenderSetup {
  std::string scene = "boxes";   // a box scene (fixtures/scenes.h) or the city (fixtures/city_scenes.h)
  std::filesystem::path model;  // non-empty: a model scene from this mesh file (scene/model.h) instead
  std::string source = "full";  // the shadow-map source (frame/shadow_map_source.h)
  double light_scale = 1.0;  // multiplies the scene's light width (the penumbrae grow with it)
  int map_size = 512;
  int screen_size = 512;
  int truth_samples = 16;  // per side of the truth's S×S light samples
  int repeats = 3;         // timed runs per technique (the median is reported)
  int cascades = 3;        // a scene lit by the sun: its cascades (1..4; 0: one map over the whole scene), each map_size²
  std::vector<std::shared_ptr<const TechniqueConfig>> techniques;  // empty: render_techniques()
  std::filesystem::path out = "render";
};

struct RenderResult {
  std::string scene_name;
  Comparison comparison;
  std::vector<std::filesystem::path> written;
};

// Throws Error naming the first setting out of range (scene, source, light scale, sizes, samples,
// repeats, cascades, techniques).
void validate_render_setup(const RenderSetup& setup);

// Creates `out` (and its parents); throws Error naming it when it cannot.
void create_output_directory(const std::filesystem::path& out);

// The setup's scene: the box scene or city `scene`, or the model in `model`, its light's width times
// `light_scale`. Throws Error for an unknown scene, a model file that cannot be loaded
// (scene/model.h) or a scaled light that does not validate.
Scene load_render_scene(const RenderSetup& setup);

// The names of the files run_render writes into `out`, in order: the truth's shadow and lit
// images, per technique its shadow, lit and error images (and on cascades its cascade overlay),
// the sheet, and last the manifest "<scene>_manifest.txt" listing the others — there only
// when the whole set was written. For probing `out` before any work (probe_output_directory).
std::vector<std::string> render_output_names(const RenderSetup& setup, const Scene& scene);

// Renders and scores every technique, then creates `out` and writes the PNGs and the sheet.
// Throws Error for an invalid setup (before writing anything).
RenderResult run_render(const Context& context, const SourceTree& tree, const RenderSetup& setup, const Scene& scene);

// `stages`: also each technique's per-stage GPU times.
void print_render_table(std::ostream& out, const RenderSetup& setup, const RenderResult& result, bool stages);

}  // namespace pn
