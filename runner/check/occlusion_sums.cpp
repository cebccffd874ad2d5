#include "check/occlusion_sums.h"

#include <algorithm>

namespace pn {

void add_occlusion_cases(std::vector<CaseResult>& results, const std::string& name, const OcclusionBatch& batch,
                         const char* taken, const char* left_out_why) {
  const int n = static_cast<int>(batch.expected.size());
  if (n == 0) return;
  Image e_counts(n, 1, 2), o_counts(n, 1, 2), e_sum(n, 1), o_sum(n, 1);
  double most = 0.0;
  for (int k = 0; k < n; ++k) {
    const OcclusionSums& e = batch.expected[static_cast<size_t>(k)];
    const OcclusionSums& o = batch.observed[static_cast<size_t>(k)];
    e_counts.at(k, 0, 0) = static_cast<float>(e.occluders), o_counts.at(k, 0, 0) = static_cast<float>(o.occluders);
    e_counts.at(k, 0, 1) = static_cast<float>(e.taken), o_counts.at(k, 0, 1) = static_cast<float>(o.taken);
    e_sum.at(k, 0) = static_cast<float>(e.depth_sum), o_sum.at(k, 0) = static_cast<float>(o.depth_sum);
    most = std::max(most, e.occluders);
  }
  const std::string count = " (" + std::to_string(n) + " queries, query k at (k, 0)";
  const std::string left =
      batch.left_out > 0 ? "; " + std::to_string(batch.left_out) + " left out: " + left_out_why : "";
  const Tolerance exact = Tolerance::exact();
  results.push_back({name + ": occluders, " + taken + count + left + ")", exact, compare(e_counts, o_counts, exact)});
  constexpr double kUnit = 1.0 / 16777216.0;  // u = 2^-24
  const Tolerance sum = Tolerance::relative((most + 1.0) * kUnit * (1.0 + most * kUnit));
  results.push_back({name + ": depth sum" + count + ")", sum, compare(e_sum, o_sum, sum)});
}

}  // namespace pn
