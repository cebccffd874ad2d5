// C++ face of glsl/vogel_pcss.glsl: its sample counts and their bound, shared
// by the pipeline's settings, the Vogel query pass and the CPU reference.
#pragma once

#include <vogel_pcss.h>  // glsl/vogel_pcss.h: PN_VOGEL_*, PN_IGN_*, shared with the shaders

namespace pn {

inline constexpr int kVogelMaxSamples = PN_VOGEL_MAX_SAMPLES;        // the loops' bound
inline constexpr int kVogelBlockerSamples = PN_VOGEL_BLOCKER_SAMPLES;  // the call's search
inline constexpr int kVogelPcfSamples = PN_VOGEL_PCF_SAMPLES;          // and its filter

}  // namespace pn
