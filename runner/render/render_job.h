// `penumbra render`, the project's main job: one scene rendered by every PCSS
// technique in the same run and compared — per technique the soft-shadow map
// and a lit image as PNG, a side-by-side sheet, and a table of GPU time and
// SSIM against exact PCSS and against the physical reference (the average of
// many hard shadows over the area light).
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "gl/context.h"
#include "pipeline/pcss_settings.h"
#include "shader/source_tree.h"

namespace pn {

struct RenderSetup {
  std::string scene = "boxes";
  int map_size = 512;
  int screen_size = 512;
  int light_samples = 8;  // per side of the physical reference's grid of point lights
  int repeats = 3;        // timed runs per technique (the median is reported)
  std::vector<PcssSettings> methods = pcss_methods();
  std::filesystem::path out = "render";
};

struct RenderRow {
  std::string method;
  double gpu_ms = 0.0;           // median total of Steps 1 (pyramid) to 6
  double ssim_exact = 0.0;       // of the soft-shadow map, against exact PCSS
  double ssim_physical = 0.0;    // against the physical reference
  double ssim_exact_lit = 0.0;   // of the lit image's luma, against exact PCSS's
  double representative_fraction = 0.0;
  double work_per_receiver = 0.0;
  std::vector<std::pair<std::string, double>> stages;  // median GPU ms per stage
};

struct RenderResult {
  std::vector<RenderRow> rows;
  std::vector<std::filesystem::path> written;
};

// Throws Error naming the first setting out of range (an unknown scene, sizes, samples, repeats).
void validate_render_setup(const RenderSetup& setup);

// Creates `out` (and its parents); throws Error naming it when it cannot.
void create_output_directory(const std::filesystem::path& out);

// Throws Error for an invalid setup (before writing anything).
RenderResult run_render(const Context& context, const SourceTree& tree, const RenderSetup& setup);

// `stages`: also each method's per-stage GPU times.
void print_render_table(std::ostream& out, const RenderSetup& setup, const RenderResult& result, bool stages);

}  // namespace pn
