// The registry of module checks behind `penumbra check`: each runs one
// module's pass over the fixtures on the GPU and compares every case with its
// CPU reference. Later modules add one entry here and one file of cases.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "check/compare.h"
#include "gl/context.h"
#include "reference/blur_reference.h"
#include "shader/source_tree.h"

namespace pn {

// What the user may set on the command line for the checks.
struct CheckOptions {
  std::optional<BlurParams> blur;  // replaces the blur check's parameter list
};

struct CheckEnvironment {
  const Context& context;
  const SourceTree& tree;  // the modules under test (--glsl-root)
  const CheckOptions& options;
};

struct CaseResult {
  std::string name;
  Tolerance tolerance;
  Comparison comparison;
  bool headline = false;  // printed under the table even when it passes: a measurement the module's docs quote
};

struct ModuleCheck {
  const char* module;   // the glsl/ module it checks, without .glsl
  const char* summary;  // what it compares against what
  std::vector<CaseResult> (*run)(const CheckEnvironment&);
};

const std::vector<ModuleCheck>& module_checks();
const ModuleCheck& find_module_check(const std::string& module);  // throws Error listing the modules

// One entry point per module check.
std::vector<CaseResult> run_blur_check(const CheckEnvironment& env);
std::vector<CaseResult> run_depth_pyramid_check(const CheckEnvironment& env);
std::vector<CaseResult> run_region_check(const CheckEnvironment& env);
std::vector<CaseResult> run_sample_table_check(const CheckEnvironment& env);
std::vector<CaseResult> run_traversal_check(const CheckEnvironment& env);
std::vector<CaseResult> run_reuse_check(const CheckEnvironment& env);
std::vector<CaseResult> run_light_model_check(const CheckEnvironment& env);
std::vector<CaseResult> run_shadow_map_check(const CheckEnvironment& env);
std::vector<CaseResult> run_pcss_regions_check(const CheckEnvironment& env);
std::vector<CaseResult> run_pipeline_check(const CheckEnvironment& env);
std::vector<CaseResult> run_pcf_check(const CheckEnvironment& env);
std::vector<CaseResult> run_poisson_pcss_check(const CheckEnvironment& env);
std::vector<CaseResult> run_truth_check(const CheckEnvironment& env);
std::vector<CaseResult> run_summed_area_check(const CheckEnvironment& env);
std::vector<CaseResult> run_savsm_check(const CheckEnvironment& env);
std::vector<CaseResult> run_minmax_mip_check(const CheckEnvironment& env);
std::vector<CaseResult> run_depth_cache_check(const CheckEnvironment& env);
std::vector<CaseResult> run_cascades_check(const CheckEnvironment& env);
std::vector<CaseResult> run_vsm_check(const CheckEnvironment& env);

}  // namespace pn
