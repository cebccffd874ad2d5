#include "bench/tables_bench.h"

#include <cstdio>
#include <string>

#include "core/bounds.h"
#include "core/error.h"
#include "core/progress.h"
#include "fixture_images/texture_fixture.h"
#include "gl/gpu_timer.h"
#include "gl/texture.h"
#include "pass_runners/summed_area_pass.h"

namespace pn {
namespace {

constexpr int kMaxSize = 4096;

TableBuildTime summary(std::size_t bytes, const std::vector<double>& gpu, const std::vector<double>& wall) {
  return {bytes, median(gpu), median(wall)};
}

nlohmann::json entry_json(const TableBuildTime& t) {
  return {{"bytes", t.bytes}, {"gpu_ms_median", t.gpu_ms}, {"wall_ms_median", t.wall_ms}};
}

}  // namespace

void validate_tables_bench(const std::vector<int>& sizes, int repeats) {
  require_list_length("table sizes", sizes.size());
  for (int n : sizes)
    if (n < 1 || n > kMaxSize) throw Error("size " + std::to_string(n) + ": expected 1.." + std::to_string(kMaxSize));
  if (repeats < 1 || repeats > 1000) throw Error("repeats " + std::to_string(repeats) + ": expected 1..1000");
}

std::vector<TablesBenchRow> bench_tables(const Context& context, const SourceTree& tree, const std::vector<int>& sizes,
                                         int repeats) {
  validate_tables_bench(sizes, repeats);
  const SummedAreaPass depth_pass(context, tree);
  const SummedAreaMomentsPass moments_pass(context, tree);
  const UnitRange range = unit_range(1.0, 100.0);
  const GpuTimer timer(context);
  std::vector<TablesBenchRow> rows;
  Progress progress("bench tables", sizes.size());
  for (int n : sizes) {
    progress.step(std::to_string(n) + "x" + std::to_string(n));
    Image depth = generate_fixture(find_fixture("noise"), n, n);
    for (float& d : depth.texels) d = 20.0f + 20.0f * d;
    const std::unique_ptr<DeviceTexture> uploaded = context.upload(depth);
    const DeviceTexture& map = *uploaded;
    // Warm-up: compiles every variant and touches every allocation path once.
    depth_pass.build(map, n, n);
    moments_pass.build(map, n, n, MomentsTableKind::fixed, range);
    moments_pass.build(map, n, n, MomentsTableKind::floating, range);
    std::vector<double> depth_gpu, depth_wall, fixed_gpu, fixed_wall, float_gpu, float_wall;
    for (int r = 0; r < repeats; ++r) {  // interleaved, so that all three see the same machine state
      const StageTime d = timer.measure([&] { depth_pass.build(map, n, n); });
      const StageTime f = timer.measure([&] { moments_pass.build(map, n, n, MomentsTableKind::fixed, range); });
      const StageTime g = timer.measure([&] { moments_pass.build(map, n, n, MomentsTableKind::floating, range); });
      depth_gpu.push_back(d.gpu_ms), depth_wall.push_back(d.wall_ms);
      fixed_gpu.push_back(f.gpu_ms), fixed_wall.push_back(f.wall_ms);
      float_gpu.push_back(g.gpu_ms), float_wall.push_back(g.wall_ms);
    }
    TablesBenchRow row;
    row.size = n, row.repeats = repeats;
    row.depth = summary(SummedAreaPass::memory_bytes(n, n), depth_gpu, depth_wall);
    row.fixed = summary(SummedAreaMomentsPass::memory_bytes(context, n, n, MomentsTableKind::fixed), fixed_gpu, fixed_wall);
    row.floating =
        summary(SummedAreaMomentsPass::memory_bytes(context, n, n, MomentsTableKind::floating), float_gpu, float_wall);
    rows.push_back(row);
  }
  return rows;
}

void print_tables_bench(std::ostream& out, const std::vector<TablesBenchRow>& rows) {
  char line[256];
  std::snprintf(line, sizeof line, "%-6s %10s %10s %11s %11s %10s %10s %11s %11s\n", "size", "depth MiB", "depth ms",
                "fixed MiB", "fixed ms", "float MiB", "float ms", "fixed/depth", "float/depth");
  out << line;
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "%-6d %10.1f %10.3f %11.1f %11.3f %10.1f %10.3f %11.2f %11.2f\n", r.size,
                  r.depth.bytes / 1048576.0, r.depth.gpu_ms, r.fixed.bytes / 1048576.0, r.fixed.gpu_ms,
                  r.floating.bytes / 1048576.0, r.floating.gpu_ms, r.fixed.gpu_ms / r.depth.gpu_ms,
                  r.floating.gpu_ms / r.depth.gpu_ms);
    out << line;
  }
  out << "ms: median GPU time (GL_TIMESTAMP pairs) of a whole build (rows, then columns) over "
      << (rows.empty() ? 0 : rows.front().repeats)
      << " interleaved runs; MiB: the table (a row-prefix table as large lives while building).\n"
         "depth: 64-bit depth sums and finite counts (RGBA32UI); fixed: moments sum q, sum q^2 mod 2^64 (RGBA32UI);\n"
         "float: moments sum (x - 1/2), sum (x - 1/2)^2 (RG32F, RGBA32F on ES).\n";
}

nlohmann::json tables_bench_json(const std::vector<TablesBenchRow>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : rows)
    out.push_back({{"size", r.size},
                   {"repeats", r.repeats},
                   {"depth_sums", entry_json(r.depth)},
                   {"moments_fixed", entry_json(r.fixed)},
                   {"moments_float", entry_json(r.floating)},
                   {"ratio_fixed_to_depth", r.fixed.gpu_ms / r.depth.gpu_ms},
                   {"ratio_float_to_depth", r.floating.gpu_ms / r.depth.gpu_ms}});
  return out;
}

}  // namespace pn
