// C++ face of glsl/pcf.glsl: the bound on a window's side, shared by the pcf
// pass and the pcf reference.
#pragma once

namespace pn {

// glsl/pcf.glsl's default PN_PCF_MAX_SIDE.
inline constexpr int kPcfMaxSide = 8192;

// pnPcf's texel fetches a receiver: the 2×2 texels around it (pcf.glsl's cost).
inline constexpr int kPcfReceiverFetches = 4;

}  // namespace pn
