// The multi-jittered generator and the §3.2 selection, on the CPU.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>

#include "sampling/sample_table_generator.h"

namespace {

// Counts of samples per thin column, thin row and n×n cell.
void check_multi_jittered(const std::vector<pn::Sample>& s, int n) {
  const int count = n * n;
  REQUIRE(s.size() == static_cast<size_t>(count));
  std::vector<int> columns(count), rows(count), cells(count);
  for (const pn::Sample& p : s) {
    REQUIRE(p.x >= 0.0f);
    REQUIRE(p.x < 1.0f);
    REQUIRE(p.y >= 0.0f);
    REQUIRE(p.y < 1.0f);
    ++columns[static_cast<size_t>(std::floor(p.x * count))];
    ++rows[static_cast<size_t>(std::floor(p.y * count))];
    ++cells[static_cast<size_t>(std::floor(p.y * n) * n + std::floor(p.x * n))];
  }
  for (int i = 0; i < count; ++i) {
    INFO("stratum " << i);
    CHECK(columns[static_cast<size_t>(i)] == 1);
    CHECK(rows[static_cast<size_t>(i)] == 1);
    CHECK(cells[static_cast<size_t>(i)] == 1);
  }
}

}  // namespace

TEST_CASE("multi-jittered sets of 1, 4, 16 and 64 samples: one per thin column, thin row and cell, for 200 seeds") {
  for (std::uint32_t seed = 1; seed <= 200; ++seed)
    for (int n : {1, 2, 4, 8}) check_multi_jittered(pn::multi_jittered_set(n, seed), n);
}

TEST_CASE("the 21x8 table: every set's groups are multi-jittered, and the table is a function of the seed") {
  const pn::SampleTable a = pn::generate_sample_table(42), b = pn::generate_sample_table(42);
  const pn::SampleTable c = pn::generate_sample_table(43);
  for (int set = 0; set < 8; ++set) {
    for (auto [n, first] : {std::pair{1, 0}, std::pair{2, 1}, std::pair{4, 5}}) {
      std::vector<pn::Sample> group;
      for (int i = 0; i < n * n; ++i) group.push_back(a.at(first + i, set));
      check_multi_jittered(group, n);
    }
  }
  size_t same = 0, differ = 0;
  for (size_t i = 0; i < a.samples.size(); ++i) {
    same += a.samples[i].x == b.samples[i].x && a.samples[i].y == b.samples[i].y;
    differ += a.samples[i].x != c.samples[i].x;
  }
  CHECK(same == a.samples.size());
  CHECK(differ > a.samples.size() / 2);
  // The 8 sets differ from each other (neighbouring pixels get different samples).
  std::set<float> firsts;
  for (int set = 0; set < 8; ++set) firsts.insert(a.at(5, set).x);
  CHECK(firsts.size() == 8);
}

TEST_CASE("selection by hand: k = floor(lb clamp(s/2, 1, 4)), columns (4^k-1)/3 ... 4(4^k-1)/3, set (x+y) mod 8") {
  const auto s1 = pn::select_samples(1, 3, 4);  // s/2 = 0.5 -> 1 -> k 0
  CHECK(s1.group_log4 == 0);
  CHECK(s1.count == 1);
  CHECK(s1.first_column == 0);
  CHECK(s1.last_column == 0);
  CHECK(s1.set == 7);
  const auto s4 = pn::select_samples(4, 5, 4);  // 2 -> k 1, columns 1..4, set 9 mod 8 = 1
  CHECK(s4.group_log4 == 1);
  CHECK(s4.first_column == 1);
  CHECK(s4.last_column == 4);
  CHECK(s4.set == 1);
  const auto s7 = pn::select_samples(7, 0, 0);  // 3.5 -> lb 1.8 -> k 1
  CHECK(s7.group_log4 == 1);
  const auto s64 = pn::select_samples(64, -3, 1);  // 32 -> clamp 4 -> k 2, columns 5..20, set (-2) mod 8 = 6
  CHECK(s64.group_log4 == 2);
  CHECK(s64.count == 16);
  CHECK(s64.first_column == 5);
  CHECK(s64.last_column == 20);
  CHECK(s64.set == 6);
}
