// Cases of the blur check: every fixture at every check size, for the paper's
// default (r 3), the identity (r 0), a narrow and a wide kernel, and the
// depth-aware variant over a step-edge and a NaN/Inf-sprinkled depth.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

#include "check/blur_tolerance.h"
#include "check/module_check.h"
#include "fixture/texture_fixture.h"
#include "gl/texture.h"
#include "passes/blur_pass.h"

namespace pn {
namespace {

struct BlurCase {
  BlurParams params;
  const char* depth_fixture;  // depth-aware cases only
};

std::vector<BlurCase> default_cases() {
  return {
      {{3, 1.0, false, 0.0}, nullptr},   // seed 000 §5.3 defaults
      {{0, 1.0, false, 0.0}, nullptr},   // identity
      {{1, 0.5, false, 0.0}, nullptr},   // narrow
      {{7, 3.0, false, 0.0}, nullptr},   // wide, larger than the small fixtures
      {{3, 1.0, true, 0.05}, "step_edge"},
      {{3, 1.0, true, 0.05}, "nonfinite"},
  };
}

std::string case_name(const char* fixture, int w, int h, const BlurCase& c) {
  char text[160];
  std::snprintf(text, sizeof text, "%s %dx%d r=%d sigma=%g", fixture, w, h, c.params.radius, c.params.sigma);
  std::string name = text;
  if (c.params.depth_aware)
    name += " depth-aware(" + std::string(c.depth_fixture) + ", tol " + std::to_string(c.params.depth_tolerance) + ")";
  return name;
}

}  // namespace

std::vector<CaseResult> run_blur_check(const CheckEnvironment& env) {
  std::vector<BlurCase> cases = default_cases();
  if (env.options.blur) {
    env.options.blur->validate();
    cases = {{*env.options.blur, env.options.blur->depth_aware ? "step_edge" : nullptr}};
  }
  const BlurPass pass(env.context, env.tree);
  std::vector<CaseResult> results;
  for (const BlurCase& c : cases) {
    for (const auto& fixture : fixtures::kTextureFixtures) {
      for (const auto& size : fixtures::kCheckSizes) {
        const Image source = generate_fixture(fixture, size.width, size.height);
        const GlObject source_texture = upload_float_texture(env.context, source);
        Image depth;
        GlObject depth_texture;
        if (c.params.depth_aware) {
          depth = generate_fixture(find_fixture(c.depth_fixture), size.width, size.height);
          depth_texture = upload_float_texture(env.context, depth);
        }
        const GlObject result =
            pass.run(source_texture, c.params.depth_aware ? &depth_texture : nullptr, size.width, size.height, c.params);
        const Image observed = read_float_texture(env.context, result, size.width, size.height, 1);
        const Image expected = c.params.depth_aware ? blur_depth_aware_reference(source, depth, c.params)
                                                    : blur_reference(source, c.params);
        const Tolerance tolerance = blur_tolerance(c.params, source);
        results.push_back({case_name(fixture.name, size.width, size.height, c), tolerance,
                           compare(expected, observed, tolerance)});
      }
    }
  }
  return results;
}

}  // namespace pn
