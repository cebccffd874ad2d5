#include "check/module_check.h"

#include "core/error.h"

namespace pn {

const std::vector<ModuleCheck>& module_checks() {
  static const std::vector<ModuleCheck> checks{
      {"blur", "separable Gaussian (two 1-D passes) vs direct 2-D convolution; depth-aware vs its 1-D definition",
       &run_blur_check},
      {"pyramid", "depth_pyramid levels vs window scans (min/max exact); any-square min/max vs square scans",
       &run_pyramid_check},
      {"region", "region Steps 1-7 (literal and centred) vs the literal CPU steps, exhaustive on small maps",
       &run_region_check},
      {"sample_table", "multi-jittered strata of the table; the 3.2 selection and scaling vs the paper's arithmetic",
       &run_sample_table_check},
      {"traversal", "leaf 1 vs brute force (exact counts); sampled / min leaves and budgets vs the CPU recursion",
       &run_traversal_check},
      {"reuse", "parent links, representatives and gathered values vs explicit parent pointers and root finding",
       &run_reuse_check},
      {"light_model", "blocker-window, search-width and penumbra widths vs runner/scene/light_model.h",
       &run_light_model_check},
      {"shadow_map", "each scene's shadow map and G-buffer vs CPU ray casts through every texel / pixel centre",
       &run_shadow_map_check},
      {"pipeline", "exact PCSS vs CPU brute force; all improvements off == exact PCSS; bad inputs; SSIM at 512^2",
       &run_pipeline_check},
      {"physical_reference", "averaged hard shadows from 4x4 light sample points vs CPU segment tests to each point",
       &run_physical_reference_check},
  };
  return checks;
}

const ModuleCheck& find_module_check(const std::string& module) {
  std::string names;
  for (const ModuleCheck& check : module_checks()) {
    if (module == check.module) return check;
    names += std::string(names.empty() ? "" : ", ") + check.module;
  }
  throw Error("module '" + module + "': no check registered; expected one of " + names);
}

}  // namespace pn
