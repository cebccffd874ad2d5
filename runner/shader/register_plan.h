// An engine's register plan for an HLSL export (`bundle --register-shift … --register-space N`,
// `check --api hlsl` with the same options, docs/integration.md): the GLSL binding N of a
// resource becomes register N + the shift of its kind, in one register space. The identity plan
// (no shift, space 0) is the export's own registers.
#pragma once

#include <string>

#include "shader/spirv_cross.h"

namespace pn {

struct RegisterPlan {
  // Added to the GLSL binding: t (textures, read-only buffers), s (their samplers), u (images,
  // read-write buffers), b (constant buffers).
  unsigned t = 0, s = 0, u = 0, b = 0;
  unsigned space = 0;

  bool identity() const { return t == 0 && s == 0 && u == 0 && b == 0 && space == 0; }
  // The register of a resource of `kind` at GLSL `binding` ('t', 's', 'u' or 'b'); a storage
  // buffer's is 't' when it is read only. A combined sampler is its texture's (t).
  char register_kind(DescriptorKind kind, bool read_only) const;
  unsigned shift(char register_kind) const;
  // "t+8 s+8 u+2 b+1, space 1"; "the export's own (no shift, space 0)".
  std::string describe() const;
};

// The largest shift and space the options take (a register number stays far inside what D3D12 and
// Vulkan allow, with the sampler shift of 64 kHlslSamplerBindingShift on top).
inline constexpr unsigned kMaxRegisterShift = 4096, kMaxRegisterSpace = 31;

// `text`: "t=8,s=8,u=2,b=1", any subset, each kind once; `space`: the --register-space value.
// Throws Error naming `option` and what was expected.
RegisterPlan parse_register_plan(const std::string& shift_text, long long space);

}  // namespace pn
