#include "device/loop_census_record.h"

#include <algorithm>

namespace pn {

void reduce_census_counts(LoopCensusRecord& r, const std::vector<std::uint32_t>& counts) {
  const std::size_t loops = r.loops.size(), stride = loops + 1;
  const int lx = r.local_size[0], ly = r.local_size[1], width = r.groups[0] * lx;
  const int per_group = lx * ly;
  const auto waves_per_group = [per_group](const CensusWaves& w) {
    return static_cast<std::size_t>((per_group + w.size - 1) / w.size);
  };
  r.mean.assign(loops, 0.0);
  for (CensusWaves& w : r.waves)
    w.most.assign(static_cast<std::size_t>(r.groups[0]) * static_cast<std::size_t>(r.groups[1]) * waves_per_group(w) * loops, 0u);
  for (int gy = 0; gy < r.groups[1]; ++gy)
    for (int gx = 0; gx < r.groups[0]; ++gx)
      for (int local = 0; local < per_group; ++local) {
        const int x = gx * lx + local % lx, y = gy * ly + local / lx;
        const std::size_t k = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
        const std::size_t group = static_cast<std::size_t>(gy) * static_cast<std::size_t>(r.groups[0]) + static_cast<std::size_t>(gx);
        for (CensusWaves& w : r.waves) {
          const std::size_t wave = group * waves_per_group(w) + static_cast<std::size_t>(local / w.size);
          for (std::size_t j = 0; j < loops; ++j)
            w.most[wave * loops + j] = std::max(w.most[wave * loops + j], counts[k * stride + j + 1]);
        }
        for (std::size_t j = 0; j < loops; ++j) r.mean[j] += counts[k * stride + j + 1];
      }
  const double n = std::max(1, r.invocations());
  for (double& m : r.mean) m /= n;
}

}  // namespace pn
