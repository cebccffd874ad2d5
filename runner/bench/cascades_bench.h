// `penumbra bench cascades` (issue 14, seed 003's Tables 1, 2 and 4): the city
// lit by the sun, every technique on cascades through the technique seam
// (compare_techniques), for each split count (0: one map over the whole
// scene), map size and first-split enlargement k: the cascades' map time,
// each technique's GPU time and frame time (maps + technique), and its SSIM and
// MAE against the ray-traced truth on light-facing pixels. Then the
// cascades fitted frame by frame along the city's camera path while the
// view stays at its first frame (a static scene, a still picture): the mean
// absolute change of each technique's visibility between consecutive frames,
// with stable and with unstable cascades — every change is shimmer.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "draw/canvas.h"
#include "gl/context.h"
#include "shader/source_tree.h"

namespace pn {

struct CascadesBenchSetup {
  std::string scene = "city";                       // fixtures/city_scenes.h
  std::vector<int> counts{0, 1, 2, 3, 4};            // split counts at `size` (0: the whole-scene map)
  std::vector<int> sizes{256, 512, 1024, 2048};      // map sizes at `count`
  std::vector<double> ks{1.0, 2.0, 4.0};             // first-split enlargements at `count`, `size`
  int count = 3, size = 1024;                        // where the other sweeps hold still
  std::vector<std::string> techniques{"pcf", "vsm", "vsm:radius=0", "fast", "savsm"};
  std::vector<std::string> path_techniques{"pcf", "fast"};  // along the camera path
  int path_frames = 12;
  int screen = 256;
  int repeats = 3;
  int truth_samples = 4;  // per side
};

// Throws Error naming the first bad setting (an unknown scene or technique, a count outside 0..4, a
// size outside 16..4096, k < 1, path frames outside 2..200, screen, repeats, truth samples). No GL.
void validate_cascades_bench_setup(const CascadesBenchSetup& setup);

struct CascadesBenchRow {
  std::string sweep;  // "count", "size" or "k": the first sweep it belongs to (a row where sweeps meet is measured once)
  int count = 0, size = 0;
  double k = 1.0;
  double maps_ms = 0.0;  // GPU time of the cascades' maps (or the one map)
  std::string technique;
  double technique_ms = 0.0;  // median GPU time of the technique on every cascade, blend included
  double frame_ms = 0.0;   // maps + technique
  double ssim = 0.0, mae = 0.0;  // against the truth, light-facing pixels
};

struct CascadesPathRow {
  std::string technique;  // or "truth (ray traced)"
  bool stable = true;
  double mean_change = 0.0;     // mean over the frames of the mean |v_f - v_(f-1)| over covered pixels
  double mean_error = 0.0;      // mean over the frames of the MAE against the truth (light-facing)
  std::vector<double> changes;  // per frame from the second
};

struct CascadesBench {
  std::string scene;
  int triangles = 0;
  int count = 0, size = 0;  // where the sweeps hold still (the setup's)
  std::vector<CascadesBenchRow> rows;
  std::vector<CascadesPathRow> path;
};

CascadesBench bench_cascades(const Context& context, const SourceTree& tree, const CascadesBenchSetup& setup);
void print_cascades_bench(std::ostream& out, const CascadesBench& bench);
nlohmann::json cascades_bench_json(const CascadesBenchSetup& setup, const CascadesBench& bench);
// Frame time against split count and map size, a line per technique; the change along the path.
Canvas cascades_bench_chart(const CascadesBench& bench, const std::string& title);

}  // namespace pn
