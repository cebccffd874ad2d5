// SPEC §4.7 Step 3's property — the "lit" decision reads the minimum over a
// square that covers the whole search region, so no receiver that a texel can
// shadow is marked lit — on the tall-blocker scene's own shadow map and G-buffer
// in one region mode. The pcss_regions check holds the exact mode to it; the
// window modes read the power-of-two window alone and miss blockers on its
// +u/+v side (issue 11), which tests/pcss_regions_gl_test.cpp keeps as a
// known failure until the module is fixed.
#pragma once

#include "check/module_check.h"
#include "modules/pcss_regions_face.h"

namespace pn {

struct LitCoverage {
  long receivers = 0;   // valid receivers with a finite depth
  long shadowable = 0;  // of them, those a texel can shadow (CPU, shadowing_blocker)
  long lit = 0;         // marked lit by the GPU (pnSearchEntry)
  long violations = 0;  // marked lit although a texel can shadow them: 0 expected
  long left_out = 0;    // lit, with a texel within float rounding of shadowing them
  CaseResult result;    // violations per pixel (1) against 0, exact
};

// Renders `scene` — the tall blocker at a 256² map and 128² screen, the boxes at 512² and 512² (their
// far walls need it) — and runs Step 3 with the pipeline's bias and refinement (PcssSettings'
// defaults) in `mode`.
LitCoverage pcss_regions_lit_coverage(const CheckEnvironment& env, RegionMode mode,
                                      const char* scene = "tall_blocker");

}  // namespace pn
