// Techniques compared on one frame of one scene, as render and bench both
// need it: each technique timed through the seam (medians), its visibility
// read back, and scored (metrics/scores.h) against the ray-traced truth and
// against exact PCSS when exact PCSS is among the techniques.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "cascades/cascade_fit.h"
#include "core/image.h"
#include "metrics/scores.h"
#include "scene/scene.h"
#include "frame/scene_frame.h"
#include "frame/technique.h"

namespace pn {

struct ComparisonSetup {
  std::string source = "full";  // shadow_map_sources()
  // A scene lit by the sun: its techniques run on these cascades (CascadedTechnique); none: on
  // one orthographic map over the whole scene. Ignored for the area light's scenes.
  std::optional<CascadeSettings> cascades;
  int screen_size = 512;
  int repeats = 3;
  int truth_samples = 16;  // per side: S×S light samples per pixel
  std::vector<const TechniqueConfig*> techniques;  // validated; not owned
  // After the timed rounds, each technique once more on programs of its own that count their
  // loops (Context::set_loop_census): TechniqueResult::census, the GPU estimate's input.
  bool census = false;
};

struct TechniqueResult {
  std::string name;
  TechniqueMeasurement measurement;
  Image visibility;                // rows from the bottom
  Scores vs_truth;
  std::optional<Scores> vs_exact;  // when exact PCSS ran
  LoopCensus census;               // its compute dispatches' loop counts (ComparisonSetup::census)
};

struct Comparison {
  Image truth;             // visibility, rows from the bottom
  double truth_ms = 0.0;   // CPU wall time of the ray tracing
  Image surface;           // SurfaceRenderer's image: albedo, N·L
  double shadow_map_ms = 0.0;
  double second_layer_ms = 0.0;  // the second layers its techniques asked for (0: none), GPU time
  std::vector<TechniqueResult> results;  // in the order of setup.techniques
  std::optional<Scores> truth_vs_exact;
  std::optional<Image> cascade_index;  // on cascades: each pixel's cascade (cascades.glsl's selection), -1 where none
  std::vector<Cascade> cascades;       // on cascades: the fitted cascades

  const TechniqueResult* find(const std::string& name) const;  // null when not run
};

// Throws Error for a bad setup (before any GL work) or a technique that fails.
Comparison compare_techniques(const Context& context, const SourceTree& tree, const Scene& scene,
                              const ComparisonSetup& setup);

}  // namespace pn

namespace pn {

// The two score tables: light-facing pixels (the headline: time, stats, SSIM and MAE against the
// truth and exact PCSS), then the whole map and the lit image; a row for the truth itself
// against exact PCSS. "-" where exact PCSS did not run.
void print_score_tables(std::ostream& out, const Comparison& comparison);

// The width of a table's technique column: the longest of `names` and the truth's row, and a gap.
int name_column_width(const std::vector<std::string>& names);

}  // namespace pn
