#include "bench/traversal_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/bounds.h"
#include "core/error.h"
#include "core/progress.h"
#include "core/seeded_random.h"
#include "fixture_images/texture_fixture.h"
#include "gl/gpu_timer.h"
#include "gl/texture.h"
#include "pass_runners/traversal_pass.h"
#include "reference/depth_pyramid_reference.h"
#include "reference/region_reference.h"

namespace pn {
namespace {

// Receivers on the ground of the boxes map: a random spot, its ground depth
// plus a little (a surface just behind the ground sample), and the literal
// power-of-two window of a search region of side 16…256 (log-uniform) around it.
std::vector<TraversalQuery> ground_receivers(const Image& map, int count) {
  const auto& boxes = find_fixture("boxes");
  SeededRandom random(0x5eed0007u);
  std::vector<TraversalQuery> queries;
  const int n = map.width;
  for (int k = 0; k < count; ++k) {
    const float x = random.uniform_float(0.0f, static_cast<float>(n)), y = random.uniform_float(0.0f, static_cast<float>(n));
    const float side = std::exp2(random.uniform_float(4.0f, 8.0f));
    const float ground = boxes_ground_depth(boxes, y, n);
    const RegionWindow w = region_reference(x, y, side, n);
    queries.push_back({{w.u, w.v, w.side, w.side}, ground + 0.002f, k % 64, k / 64});
  }
  return queries;
}

}  // namespace

void validate_traversal_bench_setup(const TraversalBenchSetup& setup) {
  require_list_length("traversal leaf sizes", setup.leaf_sides.size());
  if (setup.map_size < 16 || setup.map_size > 2048)
    throw Error("map size " + std::to_string(setup.map_size) + ": expected 16..2048");
  if (setup.receivers < 1 || setup.receivers > 1000000)
    throw Error("receivers " + std::to_string(setup.receivers) + ": expected 1..1000000");
  if (setup.repeats < 1 || setup.repeats > 1000)
    throw Error("repeats " + std::to_string(setup.repeats) + ": expected 1..1000");
  for (int leaf : setup.leaf_sides)
    if (leaf < 1 || leaf > 8192) throw Error("leaf size " + std::to_string(leaf) + ": expected 1..8192");
}

std::vector<TraversalBenchRow> bench_traversal(const Context& context, const SourceTree& tree,
                                               const TraversalBenchSetup& setup) {
  validate_traversal_bench_setup(setup);

  const int n = setup.map_size;
  const Image map = generate_fixture(find_fixture("boxes"), n, n);
  const DepthPyramid pyramid = DepthPyramidBuilder(context, tree).build(*context.upload(map), n, n, 31);
  const std::unique_ptr<DeviceTexture> table = upload_sample_table(context, generate_sample_table(kSampleTableSeed));
  const TraversalPass traversal(context, tree);
  const WindowScanPass scan(context, tree);
  const GpuTimer timer(context);
  const std::vector<TraversalQuery> queries = ground_receivers(map, setup.receivers);
  const TraversalBatch batch(context, queries);
  const double receivers = static_cast<double>(queries.size());

  const auto time_median = [&](const std::function<void()>& work) {
    work();  // warm-up
    std::vector<double> times;
    for (int r = 0; r < setup.repeats; ++r) times.push_back(timer.measure(work).gpu_ms);
    return median(times);
  };

  std::vector<TraversalBenchRow> rows;
  const auto leaf_1 = static_cast<size_t>(std::count(setup.leaf_sides.begin(), setup.leaf_sides.end(), 1));
  Progress progress("bench traversal", 1 + 2 * setup.leaf_sides.size() - leaf_1);
  progress.step("brute force, " + std::to_string(queries.size()) + " receivers");
  TraversalBenchRow brute{"brute force", 0};
  brute.gpu_ms = time_median([&] { scan.dispatch(pyramid, batch, 0.0f); });
  const std::vector<TraversalReadback> exact = batch.read();
  for (const auto& e : exact) brute.fetches_per_receiver += e.fetches / receivers;
  rows.push_back(brute);

  for (LeafMode mode : {LeafMode::sampled, LeafMode::min}) {
    for (int leaf : setup.leaf_sides) {
      if (mode == LeafMode::min && leaf == 1) continue;  // identical to sampled at leaf 1
      progress.step(std::string(mode == LeafMode::sampled ? "sampled" : "min") + " leaf " + std::to_string(leaf));
      TraversalSettings settings;
      settings.leaf_side = leaf, settings.leaf_mode = mode;
      TraversalBenchRow row{std::string(mode == LeafMode::sampled ? "sampled" : "min (HQEPCSS)") + " leaf " +
                                std::to_string(leaf),
                            leaf};
      row.gpu_ms = time_median([&] { traversal.dispatch(pyramid, *table, batch, settings); });
      const std::vector<TraversalReadback> got = batch.read();
      double with_blockers = 0;
      for (size_t k = 0; k < got.size(); ++k) {
        row.nodes_per_receiver += got[k].nodes / receivers;
        row.fetches_per_receiver += got[k].fetches / receivers;
        const double fraction_error = std::fabs(got[k].occluded_fraction() - exact[k].occluded_fraction());
        row.mean_fraction_error += fraction_error / receivers;
        row.max_fraction_error = std::max(row.max_fraction_error, fraction_error);
        if (exact[k].occluders > 0 && got[k].occluders > 0) {
          row.mean_blocker_error += std::fabs(got[k].blocker_mean() - exact[k].blocker_mean());
          ++with_blockers;
        }
      }
      if (with_blockers > 0) row.mean_blocker_error /= with_blockers;
      rows.push_back(row);
    }
  }
  for (auto& r : rows) {
    r.ns_per_receiver = r.gpu_ms * 1e6 / receivers;
    r.speedup = brute.gpu_ms / r.gpu_ms;
  }
  return rows;
}

void print_traversal_bench(std::ostream& out, const TraversalBenchSetup& setup, const std::vector<TraversalBenchRow>& rows) {
  char line[256];
  std::snprintf(line, sizeof line, "%-22s %10s %10s %9s %10s %8s %10s %10s %10s\n", "method", "ms/batch", "ns/recv",
                "nodes", "fetches", "speedup", "mean|dF|", "max|dF|", "mean|dZ|");
  out << line;
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "%-22s %10.3f %10.1f %9.1f %10.1f %8.2f %10.2e %10.2e %10.2e\n", r.method.c_str(),
                  r.gpu_ms, r.ns_per_receiver, r.nodes_per_receiver, r.fetches_per_receiver, r.speedup,
                  r.mean_fraction_error, r.max_fraction_error, r.mean_blocker_error);
    out << line;
  }
  out << setup.receivers << " receivers on the ground of the boxes fixture at " << setup.map_size << "x" << setup.map_size
      << ", power-of-two windows of search regions 16-256 texels; median GPU time of " << setup.repeats
      << " runs; nodes, fetches per receiver; dF occluded fraction and dZ blocker mean vs brute force.\n";
}

nlohmann::json traversal_bench_json(const TraversalBenchSetup& setup, const std::vector<TraversalBenchRow>& rows) {
  nlohmann::json out{{"map_size", setup.map_size}, {"receivers", setup.receivers}, {"repeats", setup.repeats}};
  for (const auto& r : rows)
    out["rows"].push_back({{"method", r.method},
                           {"leaf_side", r.leaf_side},
                           {"gpu_ms_median", r.gpu_ms},
                           {"ns_per_receiver", r.ns_per_receiver},
                           {"nodes_per_receiver", r.nodes_per_receiver},
                           {"fetches_per_receiver", r.fetches_per_receiver},
                           {"speedup_vs_brute_force", r.speedup},
                           {"mean_fraction_error", r.mean_fraction_error},
                           {"max_fraction_error", r.max_fraction_error},
                           {"mean_blocker_depth_error", r.mean_blocker_error}});
  return out;
}

}  // namespace pn
