// Poisson-disk samples in the unit disk by Bridson's algorithm ("Fast Poisson
// disk sampling in arbitrary dimensions", SIGGRAPH 2007 sketch), as seed 004
// uses for PCSS's blocker search (36 samples) and PCF (64): every two samples
// at least `min_distance` apart, all within radius 1 of the centre.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sampling/sample_table_generator.h"

namespace pn {

struct PoissonDisk {
  std::vector<Sample> points;  // in [-1, 1]², |p| <= 1
  double min_distance = 0.0;   // the r the points were generated with
};

// Bridson with radius r and 30 candidates per active point, from a seed:
// every point it accepts is at least r from all others and inside the disk.
PoissonDisk bridson_disk(double r, std::uint32_t seed, int candidates = 30);

// `count` points: Bridson's output for the largest r (shrinking by 2 % from
// 2 / sqrt(count), 16 seeded runs per r) that yields exactly `count` points;
// should every run at that r overshoot, the first `count` points of the
// smallest overshoot. Deterministic for a seed. Throws Error for count < 1 or > 4096.
PoissonDisk poisson_disk(int count, std::uint32_t seed);

// The seeds of the runner's Poisson PCSS disks (its blocker search's PN_POISSON_BLOCKER_SAMPLES,
// its PCF's PN_POISSON_PCF_SAMPLES), which the HLSL and MSL exports also ship as constants
// (glsl/exports/poisson_disks.glsl).
inline constexpr std::uint32_t kPoissonBlockerDiskSeed = 0x5eed0036u;
inline constexpr std::uint32_t kPoissonFilterDiskSeed = 0x5eed0064u;

}  // namespace pn
