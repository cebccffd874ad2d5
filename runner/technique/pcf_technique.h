// The hard shadow behind the technique seam (registry entry `pcf`): 2×2
// bilinear PCF per screen pixel (pcf.glsl's pnPcfBilinearVisibility through
// passes/pcf_shade.comp), what a hardware shadow sampler gives and the
// baseline of seed 003's tables ("PCF 2×2"). One stage, no stats.
#pragma once

#include <memory>
#include <string>

#include "frame/technique.h"

namespace pn {

// The registry's entry; override keys: bias (light-depth units, >= 0; default 0.02 as the PCSS
// family's), receiver-plane (off, on or a slope clamp's tangent: the receiver plane from the
// G-buffer's neighbours, each of the four texels against it; default off).
std::unique_ptr<TechniqueConfig> pcf_config(const char* name);

}  // namespace pn
