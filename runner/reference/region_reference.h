// CPU reference for glsl/region.glsl: seed 000 §2.2 Steps 1–7 followed
// literally — the binary form of w written out digit by digit for Steps 3–4 —
// with the readings SPEC §4.2 and docs/modules/region.md fix.
#pragma once

namespace pn {

struct RegionWindow {
  int u = 0, v = 0;  // origin (top-left texel)
  int side = 1;      // a power of two <= N
  int level = 0;     // log2(side)
  bool operator==(const RegionWindow&) const = default;
};

// The literal steps. Inputs are float texel coordinates; Step 1 is evaluated
// in float32, as the shader does. n >= 1.
RegionWindow region_reference(float x, float y, float side, int n);

// The centred option: the same side, origin round(centre − side/2) clamped into the map.
RegionWindow region_centred_reference(float x, float y, float side, int n);

}  // namespace pn
