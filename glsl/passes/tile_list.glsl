// tile_list.glsl — a dispatch over a list of 8×8 tiles instead of a grid:
// work group k handles tile pnTiles[first + k], the texels
// tile · 8 + [0, 8)², so a pass touches only the tiles a cache marked dirty
// (runner/gl/tile_list.h builds the list). The including pass defines
// PN_TILE_LIST_BINDING (its storage buffer binding) and has an 8×8 local size.

#ifndef PENUMBRA_TILE_LIST_GLSL
#define PENUMBRA_TILE_LIST_GLSL

#define PN_TILE_SIDE 8

layout(std430, binding = PN_TILE_LIST_BINDING) readonly buffer PnTileList {
  ivec2 pnTiles[];
};

// The texel this invocation handles: from the tile list when count > 0, else the dispatch's grid.
ivec2 pnTileListTexel(int first, int count) {
  if (count <= 0) return ivec2(gl_GlobalInvocationID.xy);
  int k = min(int(gl_WorkGroupID.x), count - 1);
  return pnTiles[first + k] * PN_TILE_SIDE + ivec2(gl_LocalInvocationID.xy);
}

#endif  // PENUMBRA_TILE_LIST_GLSL
