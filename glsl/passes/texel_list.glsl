// texel_list.glsl — a dispatch over a list of texels instead of a grid:
// invocation k of a run of 64-invocation work groups (8×8, flattened) handles
// texel pnTexelList.texels[first + k], so a pass touches only the texels of the
// rectangles a cache marked dirty, in one dispatch however many there are
// (runner/gl/texel_list.h builds the list). The including pass defines
// PN_TEXEL_LIST_BINDING (its storage buffer binding) and has an 8×8 local size.

#ifndef PENUMBRA_TEXEL_LIST_GLSL
#define PENUMBRA_TEXEL_LIST_GLSL

#ifndef PN_TEXEL_LIST_BINDING
#define PN_TEXEL_LIST_BINDING 7  // standalone (lint, bundle); every pass defines its own
#endif

// Named (pnTexelList), so that the HLSL and MSL exports name it too (a nameless block: `_432`).
layout(std430, binding = PN_TEXEL_LIST_BINDING) readonly buffer PnTexelList {
  ivec2 texels[];
} pnTexelList;

// The texel this invocation handles — listed texel first + k when count > 0, else the dispatch's
// grid position — and false for the invocations past the list's end.
bool pnTexelListTexel(int first, int count, out ivec2 texel) {
  if (count <= 0) {
    texel = ivec2(gl_GlobalInvocationID.xy);
    return true;
  }
  int k = int(gl_WorkGroupID.x) * 64 + int(gl_LocalInvocationIndex);
  texel = ivec2(-1);
  if (k >= count) return false;
  texel = pnTexelList.texels[first + k];
  return true;
}

#endif  // PENUMBRA_TEXEL_LIST_GLSL
