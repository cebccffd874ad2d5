// The registry of module checks behind `penumbra check`: each runs one
// module's pass over the fixtures on the GPU and compares every case with its
// CPU reference. A later module adds one entry to module_check.cpp and one file of cases.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "check/compare.h"
#include "device/query_device.h"
#include "modules/blur_face.h"
#include "scenes.h"
#include "shader/source_tree.h"
#include "texture_fixtures.h"

namespace pn {

// What the user may set on the command line for the checks.
struct CheckOptions {
  std::optional<BlurParams> blur;  // replaces the blur check's parameter list
  // --quick: each check on the fixtures of check_scenes / check_texture_fixtures below, not all of
  // them, and without its large-data cases (the same programs on more texels: pipeline's and
  // pcss_regions' 512² screens, savsm's 1024² map, summed_area's 1024² and 2048² tables,
  // depth_cache's sequence at K = 1); every program still runs (the suite's Vulkan, HLSL and
  // ES runs: docs/reliability.md).
  bool quick = false;
};

// Where the checks run: an executor (device/query_device.h) — a GL context, or a Vulkan device,
// from GLSL or from the HLSL exports — on which every pass of every check runs.
struct CheckEnvironment {
  CheckEnvironment(const QueryDevice& device, const SourceTree& tree, const CheckOptions& options)
      : device(device), tree(tree), options(options) {}
  const QueryDevice& device;
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
  const char* name;     // the glsl/ module it checks, without .glsl
  const char* summary;  // what it compares against what
  std::vector<CaseResult> (*run)(const CheckEnvironment&);
};

const std::vector<ModuleCheck>& module_checks();

// The scenes and texture fixtures a check loops over: all of them; with --quick the scene
// tall_blocker (the widest penumbrae: the longest walks; a wrong filter size shows most there) and
// the texture fixtures step_edge (an edge), nonfinite (NaN and ±Inf texels) and boxes (a
// scene-like map). Another API or a transpiled copy runs the same programs on every fixture, so
// what it can get wrong shows on these.
std::vector<fixtures::SceneFixture> check_scenes(const CheckEnvironment& env);
std::vector<fixtures::TextureFixture> check_texture_fixtures(const CheckEnvironment& env);
const ModuleCheck& find_module_check(const std::string& module);  // throws Error listing the modules

}  // namespace pn
