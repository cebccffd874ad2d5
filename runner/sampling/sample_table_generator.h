// The multi-jittered sample table of Fast PCSS (seed 000 §3.1, SPEC §4.3):
// 8 sets, each holding a 1-sample, a 4-sample and a 16-sample multi-jittered
// group (Chiu, Shirley, Wang 1994), positions in [0, 1)², stored as a 21×8
// RG32F image: column 0 the 1-sample group, 1–4 the 4-sample group, 5–20 the
// 16-sample group; row = set.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"
// glsl/sample_table.h (PN_SAMPLE_TABLE_*, shared with the shaders): angle brackets, because the
// quoted form would find this file first.
#include <sample_table.h>

namespace pn {

// The seed of the table every pass and check uploads (the pipeline, the traversal's check and
// benchmark, the figures): one table, so their results agree.
inline constexpr std::uint32_t kSampleTableSeed = 0x5eed0005u;

struct Sample {
  float x = 0.0f, y = 0.0f;
};

// One multi-jittered set of n² samples: exactly one in each of the n×n cells,
// one in each of the n² thin columns [c/n², (c+1)/n²) and one in each thin row.
// Deterministic for a given seed.
std::vector<Sample> multi_jittered_set(int n, std::uint32_t seed);

struct SampleTable {
  static constexpr int kColumns = PN_SAMPLE_TABLE_COLUMNS;
  static constexpr int kSets = PN_SAMPLE_TABLE_SETS;
  std::array<Sample, kColumns * kSets> samples{};

  const Sample& at(int column, int set) const { return samples[static_cast<size_t>(set * kColumns + column)]; }
  Image image() const;  // 21×8, 2 channels, for upload as RG32F
};

// The table for `seed`: set s, group of n² samples (n = 1, 2, 4) drawn by
// multi_jittered_set(n, a hash of (seed, s, n)).
SampleTable generate_sample_table(std::uint32_t seed);

// The table as the body of a C / C++ float array initializer, 2 · 21 · 8
// values (x, y per column, column-major within a set, sets in order): the
// RG32F texture's data, row by row, as an engine uploads it. A comment says
// the layout and the seed (`penumbra sample-table`).
std::string sample_table_text(const SampleTable& table, std::uint32_t seed);

// §3.2 selection, as the paper writes it, for a region of side s at screen pixel (x, y).
struct SampleSelection {
  int group_log4 = 0;  // k: 4^k samples
  int count = 1;       // 4^k
  int first_column = 0;  // (4^k − 1) / 3
  int last_column = 0;   // 4 (4^k − 1) / 3, inclusive
  int set = 0;           // (x + y) mod 8
};
SampleSelection select_samples(int region_side, int pixel_x, int pixel_y);

}  // namespace pn
