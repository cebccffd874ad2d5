// `penumbra render --frames N` (issue 13): N frames of an animated scene
// (scene/animated_scene.h) through one shadow-map source and one technique —
// per frame its lit image and its shadow map with the rectangles the source
// changed outlined, as PNG, and a table of the frame's share of moving
// triangles, the source's and the technique's GPU times and the share of the
// map the source changed.
#pragma once

#include <filesystem>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "gl/context.h"
#include "shader/source_tree.h"
#include "frame/technique.h"

namespace pn {

struct FramesSetup {
  std::string scene = "moving";  // fixtures/animated_scenes.h
  std::filesystem::path model;   // empty: fixtures::kAnimatedModel when it exists
  double k = 0.3;                // the motion function's share of moving triangles
  int frames = 60;
  std::string source = "dirty-rect";
  std::shared_ptr<const TechniqueConfig> technique;  // null: Fast PCSS
  int map_size = 512;
  int screen_size = 512;
  std::filesystem::path out = "render";
};

struct FrameRow {
  int frame = 0;
  double moving_share = 0.0;
  double map_ms = 0.0, technique_ms = 0.0;
  double changed_share = 0.0;  // texels of the rectangles the source changed / N² (summed, at most 1)
};

struct FramesResult {
  std::string scene_name, technique;
  std::vector<FrameRow> rows;
  std::vector<std::filesystem::path> written;
};

// Throws Error naming the first bad setting (scene, K, frames 1..1000, source, sizes 16..4096, technique).
void validate_frames_setup(const FramesSetup& setup);

// The names run_frames writes into `setup.out` (each frame's picture and map, the table), for
// probing the directory before any work (issue 39 C8, C9).
std::vector<std::string> frames_output_names(const FramesSetup& setup);

// Renders the frames, writing `<scene>_frame_NNNN.png` and `<scene>_frame_NNNN_map.png` into `out`
// (created) and `<scene>_frames.tsv`, the table.
FramesResult run_frames(const Context& context, const SourceTree& tree, const FramesSetup& setup);

void print_frames_table(std::ostream& out, const FramesSetup& setup, const FramesResult& result);

}  // namespace pn
