// correlated_multi_jitter.glsl — a stateless in-shader alternative to the
// sample table: Kensler's correlated multi-jittered sampling.
//
// description:
//   Kensler, "Correlated Multi-Jittered Sampling", Pixar Technical Memo 13-01
//   (2013). Sample s of an m×n pattern sits in cell (s mod m, s div m); its
//   position inside the cell is chosen by two hashed permutations (one for
//   all x sub-strata, one for all y sub-strata — the "correlation"), so the
//   m·n samples form a multi-jittered set: one per cell and one per thin
//   column and thin row (N-rooks), the property the sample table has
//   (SPEC §4.3), with no table and any number of independent sets. The
//   permutation is a hash on the bits below the next power of two of the
//   length, applied until the value falls inside it (cycle walking); for the
//   power-of-two lengths used here one round suffices, and the walk is
//   bounded by PN_CMJ_MAX_ROUNDS in any case.
//
// use:
//   vec2 pnCmjSample(int s, int m, int n, uint pattern)       s in [0, m·n), position in [0, 1)²
//   vec2 pnSampleStateless(int k, int index, int set, uint seed)
//        the sample-table equivalent: group of 4^k samples (2^k × 2^k), its
//        index-th sample, set `set` (as pnSampleSet gives) of the seed's sets
//
// options:
//   PN_CMJ_MAX_ROUNDS 16   bound of the cycle walk (non-power-of-two lengths)
//
// cost: about 40 integer operations per sample, no memory access.

#ifndef PENUMBRA_CORRELATED_MULTI_JITTER_GLSL
#define PENUMBRA_CORRELATED_MULTI_JITTER_GLSL

#ifndef PN_CMJ_MAX_ROUNDS
#define PN_CMJ_MAX_ROUNDS 16
#endif

// A pseudo-random permutation of [0, length), selected by `pattern`.
uint pn_cmjPermute(uint i, uint length, uint pattern) {
  uint mask = length - 1u;
  mask |= mask >> 1;
  mask |= mask >> 2;
  mask |= mask >> 4;
  mask |= mask >> 8;
  mask |= mask >> 16;
  uint v = i;
  for (int round = 0; round < PN_CMJ_MAX_ROUNDS; ++round) {
    v ^= pattern;
    v *= 0xe170893du;
    v ^= pattern >> 16;
    v ^= (v & mask) >> 4;
    v ^= pattern >> 8;
    v *= 0x0929eb3fu;
    v ^= pattern >> 23;
    v ^= (v & mask) >> 1;
    v *= 1u | (pattern >> 27);
    v *= 0x6935fa69u;
    v ^= (v & mask) >> 11;
    v *= 0x74dcb303u;
    v ^= (v & mask) >> 2;
    v *= 0x9e501cc3u;
    v ^= (v & mask) >> 2;
    v *= 0xc860a3dfu;
    v &= mask;
    v ^= v >> 5;
    if (v < length) break;
  }
  return (min(v, length - 1u) + pattern) % length;
}

// A hashed value in [0, 1) for sample i of pattern p.
float pn_cmjRandom(uint i, uint pattern) {
  uint v = i ^ pattern;
  v ^= v >> 17;
  v ^= v >> 10;
  v *= 0xb36534e5u;
  v ^= v >> 12;
  v ^= v >> 21;
  v *= 0x93fc4795u;
  v ^= 0xdf6e307fu;
  v ^= v >> 17;
  v *= 1u | (pattern >> 18);
  // 16 high bits: with at most 2^16 strata a side, stratum + jitter stays
  // strictly below the next stratum after rounding to float.
  return float(v >> 16) * (1.0 / 65536.0);
}

vec2 pnCmjSample(int s, int m, int n, uint pattern) {
  uint um = uint(max(m, 1)), un = uint(max(n, 1));
  uint us = uint(clamp(s, 0, max(m, 1) * max(n, 1) - 1));
  uint column = us % um, row = us / um;
  uint sx = pn_cmjPermute(column, um, pattern * 0xa511e9b3u);
  uint sy = pn_cmjPermute(row, un, pattern * 0x63d83595u);
  float jx = pn_cmjRandom(us, pattern * 0xa399d265u);
  float jy = pn_cmjRandom(us, pattern * 0x711ad6a5u);
  return vec2((float(column) + (float(sy) + jx) / float(un)) / float(um),
              (float(row) + (float(sx) + jy) / float(um)) / float(un));
}

vec2 pnSampleStateless(int k, int index, int set, uint seed) {
  int side = 1 << clamp(k, 0, 15);
  return pnCmjSample(index, side, side, seed * 0x9e3779b9u + uint(set) * 0x85ebca6bu + uint(k));
}

#endif  // PENUMBRA_CORRELATED_MULTI_JITTER_GLSL
