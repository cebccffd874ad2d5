// The registry of module checks behind `penumbra check`: each runs one
// module's pass over the fixtures on the GPU and compares every case with its
// CPU reference. A later module adds one entry to module_check.cpp and one file of cases.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "check/compare.h"
#include "device/query_device.h"
#include "gl/context.h"
#include "modules/blur.h"
#include "shader/source_tree.h"

namespace pn {

// What the user may set on the command line for the checks.
struct CheckOptions {
  std::optional<BlurParams> blur;  // replaces the blur check's parameter list
};

// Where the checks run: a query device (device/query_device.h) — a GL context, or a Vulkan
// device — and, on GL, the context itself for the checks whose passes are GL's.
struct CheckEnvironment {
  CheckEnvironment(const QueryDevice& device, const SourceTree& tree, const CheckOptions& options)
      : device(device), gl(dynamic_cast<const Context*>(&device)), tree(tree), options(options) {}
  const QueryDevice& device;  // where every query pass runs
  const Context* gl;          // the GL context, or null off GL
  const SourceTree& tree;     // the modules under test (--glsl-root)
  const CheckOptions& options;
  // The GL context; throws Error(ExitCode::failed) off GL (a check that runs GL passes).
  const Context& context() const;
};

struct CaseResult {
  std::string name;
  Tolerance tolerance;
  Comparison comparison;
  bool headline = false;  // printed under the table even when it passes: a measurement the module's docs quote
};

// Which of a check's cases run on an executor other than GL (check --api vulkan | hlsl): those
// whose passes are query passes (passes/query_pass.h). The rest build their structures or draw
// scenes with GL passes, which only a GL context runs.
enum class OffGl { none, every_case, query_cases };

struct ModuleCheck {
  const char* name;     // the glsl/ module it checks, without .glsl
  const char* summary;  // what it compares against what
  std::vector<CaseResult> (*run)(const CheckEnvironment&);
  OffGl off_gl = OffGl::none;
  const char* gl_only = "";  // with query_cases: the cases left to GL, in a few words
};

const std::vector<ModuleCheck>& module_checks();
const ModuleCheck& find_module_check(const std::string& module);  // throws Error listing the modules

}  // namespace pn
