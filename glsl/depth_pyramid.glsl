// depth_pyramid.glsl — decreased multi-scale shadow map (min / max / mean pyramid).
//
// description:
//   Seed 000 §2.1, SPEC §4.1. Level i (0 <= i <= L) of an N×N shadow map
//   holds, for every 2^i×2^i window lying wholly inside the map, indexed by
//   its top-left texel (u, v), 0 <= u, v <= N - 2^i:
//     (min, max, mean) of depth over [u, u + 2^i) × [v, v + 2^i).
//   Level 0 is the map itself; level i is built from level i-1 with four
//   fetches at (0,0), (h,0), (0,h), (h,h), h = 2^(i-1): the four half-size
//   windows tile the window exactly, so min of mins and max of maxes are
//   exact and the mean of means is the mean. Because every window origin is
//   kept (not only multiples of 2^i), the min/max of ANY s×s square comes
//   from four overlapping fetches at level floor(log2 s) (a 2-D sparse table).
//   Non-finite depths (NaN, ±Inf) mean "no occluder" (SPEC §3) and enter
//   the pyramid as +Inf: never below a receiver, never a NaN.
//
// storage:
//   One sampler2DArray, RGBA32F, N×N×(L+1): layer i = level i, texel (u, v) =
//   (min, max, mean, 0). Level i uses the top-left (N - 2^i + 1)² texels of
//   its layer. L = min(floor(log2 N), maximum level chosen by the builder).
//   Memory 16·N²·(L+1) bytes: 176 MiB at 1024² (L = 10), 768 MiB at 2048²
//   (L = 11); a maximum level M bounds it to 16·N²·(M+1).
//
// use:
//   vec4  pnPyramidFetch(sampler2DArray pyramid, int level, ivec2 origin)
//         (min, max, mean, 0) of the 2^level window at origin; level and
//         origin are clamped into the pyramid, so no read is out of bounds.
//   vec2  pnPyramidSquareMinMax(sampler2DArray pyramid, ivec2 origin, int side)
//         exact (min, max) of the side×side square at origin, side clamped to
//         [1, N], origin clamped so the square lies in the map; 4 fetches when
//         floor(log2 side) <= L, more (bounded by (N / 2^L)²) beyond.
//   int   pnPyramidMapSize(sampler2DArray pyramid)     N
//   int   pnPyramidMaxLevel(sampler2DArray pyramid)    L
//   int   pnPyramidLevelSize(int mapSize, int level)   N - 2^level + 1
//   build: vec4 pnPyramidLevel0(sampler2D shadowMap, ivec2 p)
//          vec4 pnPyramidCombine(sampler2DArray pyramid, int level, ivec2 origin)
//
// cost:
//   build: 1 fetch per texel for level 0, 4 per texel for each level above;
//   a window read: 1 fetch; a square min/max: 4 fetches.

#ifndef PENUMBRA_DEPTH_PYRAMID_GLSL
#define PENUMBRA_DEPTH_PYRAMID_GLSL

// +Inf: the depth of "no occluder".
float pn_pyramidFar() {
  return uintBitsToFloat(0x7f800000u);
}

float pn_pyramidSanitizeDepth(float d) {
  return (isnan(d) || isinf(d)) ? pn_pyramidFar() : d;
}

int pnPyramidMapSize(sampler2DArray pyramid) {
  return textureSize(pyramid, 0).x;
}

int pnPyramidMaxLevel(sampler2DArray pyramid) {
  return textureSize(pyramid, 0).z - 1;
}

int pnPyramidLevelSize(int mapSize, int level) {
  return mapSize - (1 << level) + 1;
}

// floor(log2(n)) for n >= 1.
int pn_pyramidFloorLog2(int n) {
  return findMSB(max(n, 1));
}

// Level 0 texel p of the shadow map (p clamped into it).
vec4 pnPyramidLevel0(sampler2D shadowMap, ivec2 p) {
  ivec2 last = textureSize(shadowMap, 0) - ivec2(1);
  float d = pn_pyramidSanitizeDepth(texelFetch(shadowMap, clamp(p, ivec2(0), last), 0).r);
  return vec4(d, d, d, 0.0);
}

vec4 pnPyramidFetch(sampler2DArray pyramid, int level, ivec2 origin) {
  int l = clamp(level, 0, pnPyramidMaxLevel(pyramid));
  int last = pnPyramidLevelSize(pnPyramidMapSize(pyramid), l) - 1;
  return texelFetch(pyramid, ivec3(clamp(origin, ivec2(0), ivec2(last)), l), 0);
}

// Texel `origin` of level `level` (>= 1) from the four level-1 windows that tile it.
vec4 pnPyramidCombine(sampler2DArray pyramid, int level, ivec2 origin) {
  int h = 1 << (max(level, 1) - 1);
  int below = max(level, 1) - 1;
  vec4 a = pnPyramidFetch(pyramid, below, origin);
  vec4 b = pnPyramidFetch(pyramid, below, origin + ivec2(h, 0));
  vec4 c = pnPyramidFetch(pyramid, below, origin + ivec2(0, h));
  vec4 d = pnPyramidFetch(pyramid, below, origin + ivec2(h, h));
  return vec4(min(min(a.x, b.x), min(c.x, d.x)),
              max(max(a.y, b.y), max(c.y, d.y)),
              ((a.z + b.z) + (c.z + d.z)) * 0.25,
              0.0);
}

vec2 pnPyramidSquareMinMax(sampler2DArray pyramid, ivec2 origin, int side) {
  int n = pnPyramidMapSize(pyramid);
  int s = clamp(side, 1, n);
  ivec2 o = clamp(origin, ivec2(0), ivec2(n - s));
  int level = min(pn_pyramidFloorLog2(s), pnPyramidMaxLevel(pyramid));
  int w = 1 << level;
  // Windows of side w at o + t*w, the last one flush with the far edge:
  // they cover the square and overlap, which min and max do not mind.
  int count = (s + w - 1) / w;  // 1 or 2 unless the level was capped
  vec2 result = vec2(pn_pyramidFar(), -pn_pyramidFar());
  for (int j = 0; j < count; ++j) {
    for (int i = 0; i < count; ++i) {
      ivec2 q = o + min(ivec2(i, j) * w, ivec2(s - w));
      vec4 t = pnPyramidFetch(pyramid, level, q);
      result = vec2(min(result.x, t.x), max(result.y, t.y));
    }
  }
  return result;
}

#endif  // PENUMBRA_DEPTH_PYRAMID_GLSL
