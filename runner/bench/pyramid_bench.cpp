#include "bench/pyramid_bench.h"

#include <cstdio>
#include <string>

#include "core/bounds.h"
#include "core/error.h"
#include "core/progress.h"
#include "fixture_images/texture_fixture.h"
#include "gl/gpu_timer.h"
#include "gl/query_device_gl.h"
#include "gl/texture.h"
#include "pass_runners/depth_pyramid_pass.h"
#include "pass_runners/minmax_mip_pass.h"
#include "pass_runners/summed_area_pass.h"
#include "reference/depth_pyramid_reference.h"

namespace pn {

void validate_pyramid_bench(const std::vector<int>& sizes, int repeats, int max_level) {
  require_list_length("pyramid sizes", sizes.size());
  for (int n : sizes) {
    validate_shadow_map_size(n, n);
    if (n > 4096) throw Error("size " + std::to_string(n) + ": expected 2..4096");
  }
  if (repeats < 1 || repeats > 1000) throw Error("repeats " + std::to_string(repeats) + ": expected 1..1000");
  pyramid_level_count(2, max_level);  // validates max_level
}

std::vector<PyramidBenchRow> bench_pyramid(const Context& context, const SourceTree& tree, const std::vector<int>& sizes,
                                           int repeats, int max_level) {
  validate_pyramid_bench(sizes, repeats, max_level);
  const DepthPyramidBuilder pyramid_builder(context, tree);
  const MinMaxMipBuilder mip_builder(context, tree);
  const SummedAreaPass sums_builder(context, tree);
  const GpuTimer timer(context);
  std::vector<PyramidBenchRow> rows;
  Progress progress("bench pyramid", sizes.size());
  for (int n : sizes) {
    progress.step(std::to_string(n) + "x" + std::to_string(n));
    const std::unique_ptr<DeviceTexture> uploaded = context.upload(generate_fixture(find_fixture("noise"), n, n));
    const DeviceTexture& map = *uploaded;
    const DepthPyramid pyramid = pyramid_builder.build(map, n, n, max_level);  // also the warm-up
    MinMaxMipChain chain = mip_builder.allocate(n);
    mip_builder.build_into(map, chain);
    sums_builder.build(map, n, n);
    std::vector<double> pyramid_gpu, pyramid_wall, mip_gpu, mip_wall, sums_gpu, first_gpu, rest_gpu;
    const int first = chain.first_level;
    // Interleaved, so that all see the same machine state.
    for (int r = 0; r < repeats; ++r) {
      const StageTime p = timer.measure([&] { pyramid_builder.build_into(map, pyramid); });
      const StageTime m = timer.measure([&] { mip_builder.build_into(map, chain); });
      const StageTime s = timer.measure([&] { sums_builder.build(map, n, n); });
      const StageTime f = timer.measure([&] { mip_builder.build_levels(map, chain, first, first); });
      pyramid_gpu.push_back(p.gpu_ms), pyramid_wall.push_back(p.wall_ms), sums_gpu.push_back(s.gpu_ms);
      mip_gpu.push_back(m.gpu_ms), mip_wall.push_back(m.wall_ms);
      // The rest of the build, paired within the round: timed on its own, a few short dispatches
      // read mostly the timer's own overhead.
      first_gpu.push_back(f.gpu_ms), rest_gpu.push_back(m.gpu_ms - f.gpu_ms);
    }
    PyramidBenchRow row{n, pyramid.levels, DepthPyramid::memory_bytes(n, pyramid.levels), median(pyramid_gpu),
                        median(pyramid_wall), MinMaxMipChain::memory_bytes(n), median(mip_gpu), median(mip_wall)};
    row.mip_first_ms = median(first_gpu), row.mip_rest_ms = median(rest_gpu);
    row.mip_dispatches = chain.top_level - first + 1;
    row.sums_bytes = SummedAreaPass::memory_bytes(n, n), row.sums_ms = median(sums_gpu), row.repeats = repeats;
    rows.push_back(row);
  }
  return rows;
}

void print_pyramid_bench(std::ostream& out, const std::vector<PyramidBenchRow>& rows) {
  char line[256];
  std::snprintf(line, sizeof line, "%-6s %6s %12s %12s %12s %12s %12s %12s %8s %10s %10s %10s %10s %10s\n", "size",
                "levels", "pyramid MiB", "pyramid ms", "(wall ms)", "mip MiB", "mip ms", "(wall ms)", "ratio", "sums MiB",
                "sums ms", "mip+sums", "first ms", "rest ms");
  out << line;
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line,
                  "%-6d %6d %12.1f %12.3f %12.3f %12.1f %12.3f %12.3f %8.2f %10.1f %10.3f %10.2f %10.3f %10.3f\n", r.size,
                  r.levels, r.pyramid_bytes / 1048576.0, r.pyramid_ms, r.pyramid_wall_ms, r.mip_bytes / 1048576.0,
                  r.mip_ms, r.mip_wall_ms, r.pyramid_ms / r.mip_ms, r.sums_bytes / 1048576.0, r.sums_ms,
                  (r.mip_ms + r.sums_ms) / r.mip_ms, r.mip_first_ms, r.mip_rest_ms);
    out << line;
  }
  out << "ms: median GPU time (GL_TIMESTAMP pairs) of a whole build over " << (rows.empty() ? 0 : rows.front().repeats)
      << " runs; ratio = pyramid / mip chain, same run; sums: the summed-area table of depth Fast PCSS's\n"
         "mip-chain traversal reads besides the chain; mip+sums = (mip + sums) / mip: what that structure costs.\n"
         "first: the chain's first dispatch alone (node level 2 from the map); rest: the median of each round's whole build\n"
         "less its first dispatch (levels 3 to log2 P): the most a single-dispatch build (SPD) could save on this device.\n";
}

nlohmann::json pyramid_bench_json(const std::vector<PyramidBenchRow>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : rows)
    out.push_back({{"size", r.size},
                   {"levels", r.levels},
                   {"repeats", r.repeats},
                   {"pyramid", {{"bytes", r.pyramid_bytes}, {"gpu_ms_median", r.pyramid_ms}, {"wall_ms_median", r.pyramid_wall_ms}}},
                   {"minmax_mip_chain", {{"bytes", r.mip_bytes}, {"gpu_ms_median", r.mip_ms}, {"wall_ms_median", r.mip_wall_ms},
                                         {"dispatches", r.mip_dispatches}, {"first_dispatch_gpu_ms_median", r.mip_first_ms},
                                         {"rest_gpu_ms_median", r.mip_rest_ms}}},
                   {"summed_area_table", {{"bytes", r.sums_bytes}, {"gpu_ms_median", r.sums_ms}}},
                   {"ratio_pyramid_to_mip_chain", r.pyramid_ms / r.mip_ms},
                   {"ratio_mip_chain_and_sums_to_mip_chain", (r.mip_ms + r.sums_ms) / r.mip_ms}});
  return out;
}

}  // namespace pn
