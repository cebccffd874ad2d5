// Cases of the sample_table check: the uploaded table is multi-jittered in
// every set and group (CPU property); the shader's §3.2 selection and scaling
// equal the paper's arithmetic for every pixel residue, region side 0…40 and
// sample index; and the stateless option (correlated_multi_jitter.glsl) gives
// multi-jittered groups of 1, 4, 16 and 64 for every set of three seeds, jittered inside their
// cells (the mean offset), groups of different sizes independent.
#include <algorithm>
#include <cmath>
#include <vector>
#include <string>

#include "check/module_check.h"
#include "core/format.h"
#include "core/query_grid.h"
#include "pass_runners/sample_table_query_pass.h"

namespace pn {
namespace {

// For a group of n² samples: how many fall in each thin column, thin row and
// cell (3 n² counts; all must be 1).
Image stratum_counts(const std::vector<Sample>& group, int n) {
  const int count = n * n;
  Image counts(3 * count, 1);
  for (int i = 0; i < count; ++i) {
    const Sample& s = group[static_cast<size_t>(i)];
    const int column = static_cast<int>(std::floor(s.x * count)), row = static_cast<int>(std::floor(s.y * count));
    const int cell = static_cast<int>(std::floor(s.y * n)) * n + static_cast<int>(std::floor(s.x * n));
    if (column >= 0 && column < count) counts.at(column, 0) += 1;
    if (row >= 0 && row < count) counts.at(count + row, 0) += 1;
    if (cell >= 0 && cell < count) counts.at(2 * count + cell, 0) += 1;
  }
  return counts;
}

}  // namespace

std::vector<CaseResult> run_sample_table_check(const CheckEnvironment& env) {
  const SampleTable table = generate_sample_table(kSampleTableSeed);
  const Tolerance exact = Tolerance::exact();
  std::vector<CaseResult> results;
  for (int set = 0; set < SampleTable::kSets; ++set)
    for (auto [n, first] : {std::pair{1, 0}, std::pair{2, 1}, std::pair{4, 5}}) {
      std::vector<Sample> group;
      for (int i = 0; i < n * n; ++i) group.push_back(table.at(first + i, set));
      const Image counts = stratum_counts(group, n);
      results.push_back({"set " + std::to_string(set) + ", " + std::to_string(n * n) +
                             " samples: one per thin column, thin row and cell",
                         exact, compare(Image(counts.width, 1, 1, 1.0f), counts, exact)});
    }

  std::vector<Query> queries;
  for (int py = -3; py <= 4; ++py)
    for (int px = -4; px <= 11; ++px)
      for (int side = 0; side <= 40; ++side)
        for (int i = 0; i < 16; ++i) queries.push_back({float(px), float(py), float(side), float(i)});
  const Image input = query_image(queries);
  const std::vector<Image> observed = SampleTableQueryPass(env.device, env.tree).run(table, input);

  Image expected_a(input.width, input.height, 4), expected_b(input.width, input.height, 4);
  for (int y = 0; y < input.height; ++y)
    for (int x = 0; x < input.width; ++x) {
      const int side = static_cast<int>(input.at(x, y, 2));
      const SampleSelection s = select_samples(side, static_cast<int>(input.at(x, y, 0)), static_cast<int>(input.at(x, y, 1)));
      const int column = s.first_column + std::min(static_cast<int>(input.at(x, y, 3)), s.count - 1);
      const Sample& q = table.at(column, s.set);
      const int extent = std::max(side, 1);
      const auto scaled = [extent](float v) {
        return static_cast<float>(std::clamp(static_cast<int>(std::floor(v * static_cast<float>(extent))), 0, extent - 1));
      };
      const float a[4] = {float(s.group_log4), float(s.first_column), float(s.last_column), float(s.set)};
      const float b[4] = {float(column), scaled(q.x), scaled(q.y), 0.0f};
      for (int c = 0; c < 4; ++c) expected_a.at(x, y, c) = a[c], expected_b.at(x, y, c) = b[c];
    }
  results.push_back({"selection (k, first, last column, set) for every pixel residue and side 0-40", exact,
                     compare(expected_a, observed[0], exact)});
  results.push_back({"selected sample's column and its texel in a region of that side", exact,
                     compare(expected_b, observed[1], exact)});

  // The stateless generator: every (seed, k, set) group multi-jittered.
  std::vector<Query> cmj;
  for (int seed : {1, 2, 12345})
    for (int k = 0; k <= 3; ++k)
      for (int set = 0; set < SampleTable::kSets; ++set)
        for (int i = 0; i < (1 << (2 * k)); ++i) cmj.push_back({float(k), float(i), float(set), float(seed)});
  const Image cmj_input = query_image(cmj);
  const Image positions = CorrelatedMultiJitterQueryPass(env.device, env.tree).run(cmj_input);
  size_t at = 0;
  // Jitter: each sample's offset inside its fine cell, frac(x · n²) and frac(y · n²), uniform on [0, 1)
  // (mean 1/2; the sd of the mean over these 2,016 samples is 0.007): the sample is not at a fixed
  // point of its cell. And groups of different sizes independent: a set's first samples of the
  // 4-, 16- and 64-sample groups sit at different offsets in their cells.
  double offsets = 0.0;
  int jittered = 0;
  std::vector<std::vector<float>> first_offsets(3 * SampleTable::kSets);
  for (int seed : {1, 2, 12345})
    for (int k = 0; k <= 3; ++k) {
      const int n = 1 << k;
      std::vector<Image> per_set;
      std::vector<std::pair<float, float>> firsts;
      for (int set = 0; set < SampleTable::kSets; ++set) {
        std::vector<Sample> group;
        for (int i = 0; i < n * n; ++i, ++at) {
          const int x = static_cast<int>(at) % cmj_input.width, y = static_cast<int>(at) / cmj_input.width;
          group.push_back({positions.at(x, y, 0), positions.at(x, y, 1)});
          if (k > 0) {
            const float cells = static_cast<float>(n * n);
            const float ox = group.back().x * cells - std::floor(group.back().x * cells);
            const float oy = group.back().y * cells - std::floor(group.back().y * cells);
            offsets += ox + oy, jittered += 2;
            if (i == 0) first_offsets[static_cast<size_t>((seed == 1 ? 0 : seed == 2 ? 1 : 2) * SampleTable::kSets + set)].push_back(ox);
          }
        }
        firsts.emplace_back(group.front().x, group.front().y);
        per_set.push_back(stratum_counts(group, n));
      }
      // All sets of this seed and k side by side: every count must be 1.
      Image all(per_set.front().width * SampleTable::kSets, 1);
      for (int set = 0; set < SampleTable::kSets; ++set)
        for (int i = 0; i < per_set.front().width; ++i) all.at(set * per_set.front().width + i, 0) = per_set[static_cast<size_t>(set)].at(i, 0);
      results.push_back({"stateless (Kensler) seed " + std::to_string(seed) + ", " + std::to_string(n * n) +
                             " samples, 8 sets: one per thin column, thin row and cell",
                         exact, compare(Image(all.width, 1, 1, 1.0f), all, exact)});
      // Independent sets: the first sample differs in every set.
      std::sort(firsts.begin(), firsts.end());
      const auto distinct = std::unique(firsts.begin(), firsts.end()) - firsts.begin();
      results.push_back({"stateless (Kensler) seed " + std::to_string(seed) + ", " + std::to_string(n * n) +
                             " samples: the 8 sets' first samples are all different",
                         exact, compare(Image(1, 1, 1, 8.0f), Image(1, 1, 1, static_cast<float>(distinct)), exact)});
    }
  const double mean = offsets / jittered;
  results.push_back({"stateless (Kensler): samples jittered inside their cells (mean offset " +
                         format_number("%.3f", mean) + " of " + std::to_string(jittered) + ", within 0.45..0.55)",
                     exact, compare(Image(1, 1, 1, 1.0f), Image(1, 1, 1, mean > 0.45 && mean < 0.55 ? 1.0f : 0.0f), exact)});
  int independent = 0;
  for (std::vector<float>& f : first_offsets) {
    std::sort(f.begin(), f.end());
    independent += std::unique(f.begin(), f.end()) == f.end() ? 1 : 0;
  }
  results.push_back({"stateless (Kensler): a set's 4-, 16- and 64-sample groups independent (their first samples' "
                         "offsets in their cells differ) in " + std::to_string(independent) + " of " +
                         std::to_string(first_offsets.size()) + " (seed, set) pairs",
                     exact, compare(Image(1, 1, 1, static_cast<float>(first_offsets.size())),
                                    Image(1, 1, 1, static_cast<float>(independent)), exact)});
  return results;
}

}  // namespace pn
