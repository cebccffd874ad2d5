// `penumbra bench cache` (issue 13, the seed's Fig. 9): frames of an animated
// scene with hundreds of boxes through each shadow-map source — the full
// render, the seed's two-map cache, the dirty-rectangle cache — for each share
// K of moving triangles and each map size: per frame the GPU time of the
// shadow-map stage (drawing, composition and the update of Fast PCSS's mip
// chain) and of the whole Fast PCSS frame (that stage plus the technique),
// medians over the frames. The sources run frame by frame in turn (each
// frame starting with the next one, each stage on an idle GPU), so a machine
// whose speed drifts slows them alike and none pays for another's leftovers.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "draw/canvas.h"
#include "gl/context.h"
#include "shader/source_tree.h"

namespace pn {

struct CacheBenchSetup {
  std::string scene = "moving_city";  // fixtures/animated_scenes.h
  std::string model;                  // the scene's model file; empty: fixtures::kAnimatedModel when it exists
  std::vector<int> sizes{1024, 2048};
  std::vector<double> ks{0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
  std::vector<std::string> sources{"full", "two-map", "dirty-rect"};
  int frames = 20;  // timed frames, after `warmup` untimed ones (the first draws everything)
  int warmup = 3;
  int screen = 512;  // Fast PCSS's screen
};

// Throws Error naming the first bad setting: an unknown scene or source, K outside [0, 1], a size
// outside 16..4096, frames outside 1..1000, warm-up outside 1..100, a screen outside 16..4096, an
// empty or too long list. No GL.
void validate_cache_bench_setup(const CacheBenchSetup& setup);

struct CacheBenchRow {
  int size = 0;
  double k = 0.0;              // asked of the motion function
  double moving_share = 0.0;   // what it gave: mean moving triangles / movable triangles over the timed frames
  std::string source;
  double map_ms = 0.0;         // median GPU time of the shadow-map stage
  double map_mean_ms = 0.0;    // its mean (the frames where objects start or stop count in full)
  double fast_ms = 0.0;        // median of Fast PCSS's own stages
  double frame_ms = 0.0;       // median of (shadow-map stage + Fast PCSS) per frame
  double redrawn_share = 0.0;  // mean over the frames of the texels drawn into / N² (rectangles summed)
};

struct CacheBench {
  std::string scene;
  int triangles = 0;  // drawn per full render
  std::vector<CacheBenchRow> rows;  // per size, per K, per source
};

CacheBench bench_cache(const Context& context, const SourceTree& tree, const CacheBenchSetup& setup);
void print_cache_bench(std::ostream& out, const CacheBench& bench);
nlohmann::json cache_bench_json(const CacheBenchSetup& setup, const CacheBench& bench);

// The seed's Fig. 9 for this run: the shadow-map stage's GPU ms and the whole Fast PCSS frame's
// rate (frames a second) against K, a line per source and map size. `title` heads it.
Canvas cache_bench_chart(const CacheBench& bench, const std::string& title);

}  // namespace pn
