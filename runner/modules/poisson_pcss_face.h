// C++ face of glsl/poisson_pcss.glsl: its sample counts and the disk's bound,
// shared by the Poisson query pass, the pipeline's settings and the CLI's
// disk generator.
#pragma once

#include <poisson_pcss.h>  // glsl/poisson_pcss.h: PN_POISSON_*, shared with the shaders

namespace pn {

inline constexpr int kPoissonMaxSamples = PN_POISSON_MAX_SAMPLES;        // the disk array's size
inline constexpr int kPoissonBlockerSamples = PN_POISSON_BLOCKER_SAMPLES;  // Poisson PCSS's search
inline constexpr int kPoissonPcfSamples = PN_POISSON_PCF_SAMPLES;          // and its filter

}  // namespace pn
