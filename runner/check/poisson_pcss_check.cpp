// Cases of the poisson_pcss check: glsl/poisson_pcss.glsl through
// passes/poisson_pcss_query.comp against poisson_pcss_reference (the
// definition in double), on every fixture at 257×257 (the raw maps: NaN and
// ±Inf texels included), for disks of diameter 0…700 texels centred inside the
// map, straddling an edge or a corner, and wholly outside; rotation off
// ((1, 0)) and on (a seeded angle per query); receivers at the centre texel's
// depth (bias 0: a texel equal to dP - bias must not occlude), random with
// bias 0.01, above and below every depth, NaN and +Inf. Two disks:
// - the pipeline's 64-point PCF disk read in place from a uniform block
//   (PN_POISSON_DISK_ARRAY, pnPoissonOcclusionDisk, what pcss_poisson.comp
//   does): counts 1, 16, 36, 64 and the clamped 0, 70, -3;
// - the constant array pasted into the pass from `penumbra poisson --count 16
//   --seed 1`, read in place (pnPoissonOcclusionDisk): counts 1, 9, 16 and the
//   clamped 0, 40 — which also checks that the pasted text is the generator's disk.
// Occluder and sample counts must be exact; the depth sum is a float sum of
// n <= 64 non-negative terms: relative error <= (n + 1) u (1 + n u), u = 2^-24
// (as in the pcf check). A query with a sample that lies within
// 4 FLT_EPSILON (|p| + s/2 + 1) of a texel edge of the map (float rounding of
// its position may put it in either texel), or, with bias != 0, a sampled
// texel within one ulp of dP - bias, is left out; the number is printed, and a
// last case requires it to stay below 5 % of the queries.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

#include "check/module_check.h"
#include "check/occlusion_sums.h"
#include "core/error.h"
#include "core/seeded_random.h"
#include "fixture_images/texture_fixture.h"
#include "gl/texture.h"
#include "pass_runners/poisson_pcss_pass.h"
#include "poisson_pcss.h"
#include "reference/poisson_pcss_reference.h"
#include "sampling/poisson_disk.h"

namespace pn {
namespace {

constexpr int kMapSize = 257;
constexpr std::uint32_t kBlockDiskSeed = 0x5eed0064u;  // the pipeline's PCF disk

// Whether float rounding may change which texel a sample reads, or how a read texel compares.
bool ambiguous(const Image& map, const std::vector<Sample>& points, const PoissonPcssQuery& q) {
  const int count = std::clamp(q.count, 0, static_cast<int>(points.size()));
  const double t = q.receiver_depth - q.bias;
  const double tie = 2.0 * FLT_EPSILON * std::max(std::fabs(t), static_cast<double>(FLT_MIN));
  for (int k = 0; k < count; ++k) {
    const PoissonPcssPosition p = poisson_pcss_position(q, points[static_cast<size_t>(k)]);
    const double margin = 4.0 * FLT_EPSILON * (std::max(std::fabs(p.x), std::fabs(p.y)) + 0.5 * q.diameter + 1.0);
    if (!(p.x >= -margin && p.y >= -margin && p.x < map.width + margin && p.y < map.height + margin)) continue;
    const auto near_edge = [margin](double v) { return std::fabs(v - std::round(v)) <= margin; };
    if (near_edge(p.x) || near_edge(p.y)) return true;
    if (q.bias != 0.0 && p.x >= 0.0 && p.y >= 0.0 && p.x < map.width && p.y < map.height &&
        std::fabs(map.at(static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y))) - t) <= tie)
      return true;
  }
  return false;
}

OcclusionSums sums(const PoissonPcssSums& s) {
  return {static_cast<double>(s.occluders), s.depth_sum, static_cast<double>(s.samples)};
}

OcclusionSums sums(const PoissonPcssGpuResult& s) { return {s.occluders, s.depth_sum, s.samples}; }

}  // namespace

std::vector<CaseResult> run_poisson_pcss_check(const CheckEnvironment& env) {
  const PoissonPcssQueryPass pass(env.device, env.tree);
  const std::vector<Sample> block_disk = poisson_disk(PN_POISSON_MAX_SAMPLES, kBlockDiskSeed).points;
  const std::vector<Sample> const_disk = poisson_disk(kPoissonQueryConstCount, kPoissonQueryConstSeed).points;
  std::vector<CaseResult> results;
  long queries_total = 0, left_out_total = 0;
  SeededRandom random(0x5eed0010u);

  for (const auto& fixture : check_texture_fixtures(env)) {
    const Image map = generate_fixture(fixture, kMapSize, kMapSize);
    for (float d : map.texels)
      if (std::isfinite(d) && d < 0.0f) throw Error(std::string("poisson_pcss check: fixture '") + fixture.name + "' has depths < 0");
    const std::unique_ptr<DeviceTexture> uploaded = env.device.upload(map);
    const DeviceTexture& texture = *uploaded;
    const std::string label = std::string(fixture.name) + " " + std::to_string(kMapSize) + "x" + std::to_string(kMapSize);

    for (const PoissonDiskSource source :
         {PoissonDiskSource::block, PoissonDiskSource::constant}) {
      const bool constant = source == PoissonDiskSource::constant;
      const std::vector<Sample>& points = constant ? const_disk : block_disk;
      const std::vector<int> counts = constant ? std::vector<int>{1, 9, 16, 0, 40}
                                               : std::vector<int>{1, 16, 36, PN_POISSON_MAX_SAMPLES, 0,
                                                                  PN_POISSON_MAX_SAMPLES + 6, -3};
      std::vector<PoissonPcssGpuQuery> gpu;
      std::vector<PoissonPcssQuery> cpu;
      for (const bool rotate : {false, true})
        for (const float diameter : {0.0f, 0.5f, 1.0f, 2.5f, 7.0f, 20.0f, 64.0f, 150.0f, 700.0f})
          for (int placement = 0; placement < 4; ++placement)
            for (int repeat = 0; repeat < 6; ++repeat) {
              const float n = static_cast<float>(kMapSize), r = 0.5f * diameter;
              float x = random.uniform_float(0.0f, n), y = random.uniform_float(0.0f, n);
              if (placement == 1) x = random.uniform_float(-0.5f, 0.5f) * (r + 1.0f);  // straddling the left edge
              if (placement == 2) {  // straddling the bottom-right corner
                x = n + random.uniform_float(-0.5f, 0.5f) * (r + 1.0f);
                y = n + random.uniform_float(-0.5f, 0.5f) * (r + 1.0f);
              }
              if (placement == 3) y = -r - random.uniform_float(1.0f, 20.0f);  // wholly above the map
              const int count = counts[static_cast<size_t>(gpu.size()) % counts.size()];
              const float angle = random.uniform_float(0.0f, 6.2831853f);
              const float rx = rotate ? std::cos(angle) : 1.0f, ry = rotate ? std::sin(angle) : 0.0f;
              float receiver = 0.0f, bias = 0.0f;
              switch (repeat) {
                case 0: {  // the centre texel's depth, bias 0
                  const int cx = std::clamp(static_cast<int>(std::floor(x)), 0, kMapSize - 1);
                  const int cy = std::clamp(static_cast<int>(std::floor(y)), 0, kMapSize - 1);
                  receiver = map.at(cx, cy);
                  break;
                }
                case 1: receiver = random.uniform_float(0.0f, 1.1f), bias = 0.01f; break;
                case 2: receiver = 1.5f; break;
                case 3: receiver = -0.5f; break;
                case 4: receiver = NAN; break;
                default: receiver = INFINITY; break;
              }
              gpu.push_back({x, y, diameter, receiver, bias, count, rx, ry});
              cpu.push_back({x, y, diameter, receiver, bias, count, rx, ry});
            }
      const std::vector<PoissonPcssGpuResult> observed = pass.run(texture, block_disk, source, gpu);
      OcclusionBatch groups[2];  // rotation off, on
      BoundedElements ratios;  // the sums through the module's helpers: odd queries the blocker mean, even the fraction
      for (size_t k = 0; k < cpu.size(); ++k) {
        OcclusionBatch& g = groups[cpu[k].rotation_y != 0.0 || cpu[k].rotation_x != 1.0 ? 1 : 0];
        if (ambiguous(map, points, cpu[k])) {
          ++g.left_out;
          continue;
        }
        const auto expected = poisson_pcss_reference(map, points, cpu[k]);
        g.expected.push_back(sums(expected));
        g.observed.push_back(sums(observed[k]));
        const double occluders = sums(expected).occluders, samples = sums(expected).taken;
        const double ratio = k % 2 == 1 ? (occluders > 0.0 ? sums(expected).depth_sum / occluders : 0.0)
                                        : (samples > 0.0 ? occluders / samples : 0.0);
        // A float sum of n <= 64 terms and a quotient: (n + 2) u of the value.
        ratios.add(ratio, observed[k].ratio, (samples + 2.0) * 0x1p-24 * std::fabs(ratio) + 1e-30, static_cast<int>(k), 0, 0);
      }
      queries_total += static_cast<long>(cpu.size());
      left_out_total += groups[0].left_out + groups[1].left_out;
      const std::string disk = constant ? " constant disk (16 in place, pnPoissonOcclusionDisk)"
                                        : " block disk (64 in place, pnPoissonOcclusionDisk)";
      add_occlusion_cases(results, label + disk + ", rotation off", groups[0], "samples", "a sample on a texel edge or a tie");
      add_occlusion_cases(results, label + disk + ", rotation on", groups[1], "samples", "a sample on a texel edge or a tie");
      Tolerance tolerance;
      const Comparison c = compare_bounded(ratios, tolerance);
      results.push_back({label + disk + ": pnPoissonBlockerMean (odd queries) or pnPoissonOccludedFraction (even) of "
                                        "the sums vs the quotient in double (query k at (k, 0))",
                         tolerance, c});
    }
  }
  const bool few = left_out_total * 20 <= queries_total;
  const Image want(1, 1, 1, 1.0f), got(1, 1, 1, few ? 1.0f : 0.0f);
  results.push_back({"queries left out for rounding: " + std::to_string(left_out_total) + " of " +
                         std::to_string(queries_total) + " (<= 5 %)",
                     Tolerance::exact(), compare(want, got, Tolerance::exact())});
  return results;
}

}  // namespace pn
