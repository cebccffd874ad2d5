#include "sampling/sample_table_generator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "core/seeded_random.h"

namespace pn {

std::vector<Sample> multi_jittered_set(int n, std::uint32_t seed) {
  SeededRandom random(seed);
  const int count = n * n;
  // 16 random bits of jitter: the sample stays strictly inside its thin
  // column and row even after rounding to float.
  const auto jitter = [&] { return random.uniform_int(0, 65535) / 65536.0; };
  std::vector<Sample> s(static_cast<size_t>(count));
  // Canonical arrangement: cell (i, j) holds the sample of thin column i·n + j and thin row j·n + i.
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      s[static_cast<size_t>(j * n + i)].x = static_cast<float>((i * n + j + jitter()) / count);
      s[static_cast<size_t>(j * n + i)].y = static_cast<float>((j * n + i + jitter()) / count);
    }
  // Shuffle the x coordinates among the cells of each cell column, and the y
  // coordinates among the cells of each cell row: cells and thin strata keep one sample each.
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n - 1; ++j) {
      const int k = random.uniform_int(j, n - 1);
      std::swap(s[static_cast<size_t>(j * n + i)].x, s[static_cast<size_t>(k * n + i)].x);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n - 1; ++i) {
      const int k = random.uniform_int(i, n - 1);
      std::swap(s[static_cast<size_t>(j * n + i)].y, s[static_cast<size_t>(j * n + k)].y);
    }
  return s;
}

Image SampleTable::image() const {
  Image out(kColumns, kSets, 2);
  for (int set = 0; set < kSets; ++set)
    for (int column = 0; column < kColumns; ++column) {
      out.at(column, set, 0) = at(column, set).x;
      out.at(column, set, 1) = at(column, set).y;
    }
  return out;
}

SampleTable generate_sample_table(std::uint32_t seed) {
  SampleTable table;
  SeededRandom seeds(seed);
  for (int set = 0; set < SampleTable::kSets; ++set) {
    int column = 0;
    for (int n : {1, 2, 4}) {
      const auto group = multi_jittered_set(n, static_cast<std::uint32_t>(seeds.uniform_int(0, 0x7fffffff)));
      for (const Sample& sample : group) table.samples[static_cast<size_t>(set * SampleTable::kColumns + column++)] = sample;
    }
  }
  return table;
}

SampleSelection select_samples(int region_side, int pixel_x, int pixel_y) {
  SampleSelection s;
  // Step 1: k = s / 2, limited to 1…4, then k = lb k.
  const double k = std::clamp(region_side / 2.0, 1.0, 4.0);
  s.group_log4 = static_cast<int>(std::floor(std::log2(k)));
  s.count = 1 << (2 * s.group_log4);
  // Step 2: set n = (x + y) mod 8 (a non-negative residue), columns (4^k − 1)/3 … 4(4^k − 1)/3.
  s.set = ((pixel_x + pixel_y) % 8 + 8) % 8;
  s.first_column = (s.count - 1) / 3;
  s.last_column = 4 * (s.count - 1) / 3;
  return s;
}

std::string sample_table_text(const SampleTable& table, std::uint32_t seed) {
  std::string out = "// Fast PCSS's multi-jittered sample table (sample_table.glsl), seed " + std::to_string(seed) + ": a " +
                    std::to_string(SampleTable::kColumns) + "x" + std::to_string(SampleTable::kSets) +
                    " RG32F texture,\n// row = set, columns 0 | 1-4 | 5-20 = the 1-, 4- and 16-sample groups; (x, y) "
                    "per texel.\n";
  char value[64];
  for (int set = 0; set < SampleTable::kSets; ++set) {
    for (int column = 0; column < SampleTable::kColumns; ++column) {
      const Sample& s = table.at(column, set);
      std::snprintf(value, sizeof value, "%s%.9gf, %.9gf,", column % 4 == 0 ? (column ? "\n    " : "    ") : " ",
                    s.x, s.y);
      out += value;
    }
    out += "\n";
  }
  return out;
}

}  // namespace pn
