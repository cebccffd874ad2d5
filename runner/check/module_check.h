// The registry of module checks behind `penumbra check`: each runs one
// module's pass over the fixtures on the GPU and compares every case with its
// CPU reference. A later module adds one entry to module_check.cpp and one file of cases.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "check/compare.h"
#include "gl/context.h"
#include "modules/blur.h"
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
  const char* name;     // the glsl/ module it checks, without .glsl
  const char* summary;  // what it compares against what
  std::vector<CaseResult> (*run)(const CheckEnvironment&);
};

const std::vector<ModuleCheck>& module_checks();
const ModuleCheck& find_module_check(const std::string& module);  // throws Error listing the modules

}  // namespace pn
