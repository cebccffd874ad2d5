// Cases of the vogel_pcss check: glsl/vogel_pcss.glsl through
// passes/vogel_pcss_query.comp against vogel_pcss_reference (the definition in
// double), on every fixture at 257×257 (the raw maps: NaN and ±Inf texels
// included), for disks of diameter 0…700 texels centred inside the map,
// straddling an edge or a corner, and wholly outside; counts 1…128 and the
// clamped 0, 200, -3; turns 0, just below 1 and random; receivers at the centre
// texel's depth (bias 0), random with bias 0.01, above and below every depth,
// NaN and +Inf; a receiver plane (gradient up to 0.05 a texel) on every third
// query; and the rotation noise at pixel centres up to 4096.
//
// Tolerances. A GPU's sin and cos are not correctly rounded: the bound used is
// Vulkan's, absolute error <= 2^-11 on [-π, π] (GLSL's own spec states none),
// the call's argument range. Sample k of n at radius r = s/2 then lies within
//   e = r (2^-11 + δθ + 8u) + 4u (|c| + r + 1),  δθ = 2π · 4u (0.382 k + 2)
// texels (per axis; u = 2^-24) of its position in double, and the reference
// gives it every verdict a position in that square can have (texels around it
// that disagree, a map edge, or a depth within 4 FLT_EPSILON of the terms of
// its threshold t + g · (q + 1/2 - c), t = dP - bias, when bias or g are not 0):
// occluders and depth sum must lie in the resulting interval
// (the sum widened by the float sum's relative bound (n+1) u (1 + n u)); the
// sample count is exact. A last case requires the samples left open so to stay
// under 2 % — the check's teeth: a wrong radius, angle or count moves samples
// by far more than e. The noise: fract(z · fract(x q.x + y q.y)) in float is
// within 53 u (3.1 (x |q.x| + y |q.y|) + 2) of its value in double (turns,
// compared on the circle).
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

#include "check/disk_layouts.h"
#include "check/module_check.h"
#include "core/error.h"
#include "core/seeded_random.h"
#include "fixture_images/texture_fixture.h"
#include "gl/texture.h"
#include "modules/vogel_pcss_face.h"
#include "pass_runners/vogel_pcss_pass.h"
#include "reference/vogel_pcss_reference.h"

namespace pn {
namespace {

constexpr int kMapSize = 257;
constexpr double kUnit = kFloatUnit;
constexpr double kAmbiguousLimit = 0.02;  // samples left open by rounding, at most

}  // namespace

std::vector<CaseResult> run_vogel_pcss_check(const CheckEnvironment& env) {
  const VogelPcssQueryPass pass(env.device, env.tree);
  std::vector<CaseResult> results;
  long samples_total = 0, ambiguous_total = 0;
  BoundedElements noise;
  SeededRandom random(0x5eed0070u);
  const std::vector<int> counts{1, 8, 16, 32, 64, kVogelMaxSamples, 0, kVogelMaxSamples + 72, -3};

  for (const auto& fixture : check_texture_fixtures(env)) {
    const Image map = generate_fixture(fixture, kMapSize, kMapSize);
    const std::unique_ptr<DeviceTexture> uploaded = env.device.upload(map);
    const DeviceTexture& texture = *uploaded;
    const std::string label = std::string(fixture.name) + " " + std::to_string(kMapSize) + "x" + std::to_string(kMapSize);
    std::vector<VogelPcssGpuQuery> gpu;
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
          const int count = counts[gpu.size() % counts.size()];
          const float turn = gpu.size() % 7 == 0 ? 0.0f : gpu.size() % 7 == 1 ? 0.99999994f
                                                                              : random.uniform_float(0.0f, 1.0f);
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
          // A receiver plane on every third query: up to 0.05 light depth a texel (the fixtures' depths are
          // about 0..1 over 257 texels).
          const bool plane = gpu.size() % 3 == 2;
          const float gx = plane ? random.uniform_float(-0.05f, 0.05f) : 0.0f;
          const float gy = plane ? random.uniform_float(-0.05f, 0.05f) : 0.0f;
          gpu.push_back({x, y, diameter, receiver, bias, count, turn, gx, gy});
        }
    for (int k = 0; k < 64; ++k) {  // the noise at pixel centres across a 4096² screen, no samples
      const float x = std::floor(random.uniform_float(0.0f, 4096.0f)) + 0.5f;
      const float y = std::floor(random.uniform_float(0.0f, 4096.0f)) + 0.5f;
      VogelPcssGpuQuery q{x, y, 1.0f, 0.5f, 0.0f, 0, 0.0f, 0.0f, 0.0f};
      q.estimate_turn = k % 2 == 1;  // every other one the one call's turn at that pixel (its centre's noise)
      gpu.push_back(q);
    }
    const std::vector<VogelPcssGpuResult> observed = pass.run(texture, gpu);

    BoundedElements occluders, sums, samples;
    for (size_t k = 0; k < gpu.size(); ++k) {
      const VogelPcssGpuQuery& g = gpu[k];
      const VogelPcssQuery q{g.centre_x, g.centre_y, g.diameter, g.receiver_depth, g.bias,
                             g.count,    g.turn,     g.gradient_x, g.gradient_y};
      // The threshold's rounding: none for t = dP exactly (bias 0, no plane), else within
      // 4 FLT_EPSILON of its terms (dP - bias, then the plane's two products and sums).
      const bool rounded = g.bias != 0.0f || g.gradient_x != 0.0f || g.gradient_y != 0.0f;
      const VogelPcssBounds b = vogel_pcss_bounds(map, q, [&q](int i, int) { return vogel_position_error(q, i); },
                                                  rounded ? 4.0 * FLT_EPSILON : 0.0);
      const VogelPcssGpuResult& o = observed[k];
      const int x = static_cast<int>(k);
      occluders.add_interval(b.occluders_lo, b.occluders_hi, o.occluders, x, 0);
      const double rel = (b.occluders_hi + 1.0) * kUnit * (1.0 + b.occluders_hi * kUnit);
      sums.add_interval(b.depth_sum_lo * (1.0 - rel), b.depth_sum_hi * (1.0 + rel), o.depth_sum, x, 0);
      samples.add(static_cast<double>(b.samples), o.samples, 0.0, x, 0);
      samples_total += b.samples;
      ambiguous_total += b.ambiguous;
      double e = interleaved_gradient_noise(g.centre_x, g.centre_y);
      if (o.noise - e > 0.5) e += 1.0;  // turns: compared on the circle
      if (e - o.noise > 0.5) e -= 1.0;
      noise.add(e, o.noise, vogel_noise_bound(g.centre_x, g.centre_y), x, 0);
    }
    const std::string count = " (" + std::to_string(gpu.size()) + " queries, query k at (k, 0))";
    const auto add = [&](const std::string& what, const BoundedElements& elements) {
      Tolerance tolerance = Tolerance::absolute(0.0);
      const Comparison c = compare_bounded(elements, tolerance);
      results.push_back({label + ": " + what + count, tolerance, c});
    };
    add("occluders within the rounding interval", occluders);
    add("samples (exact)", samples);
    add("depth sum within the rounding interval", sums);
  }
  Tolerance noise_tolerance = Tolerance::absolute(0.0);
  const Comparison noise_result = compare_bounded(noise, noise_tolerance);
  results.push_back({"pnInterleavedGradientNoise at every query's centre, and pnVogelPcssEstimate's turn at 32 pixels "
                     "(its centre's), vs double (turns, on the circle)",
                     noise_tolerance, noise_result});
  const double fraction = samples_total > 0 ? static_cast<double>(ambiguous_total) / samples_total : 0.0;
  BoundedElements open;
  open.add(0.0, static_cast<float>(fraction), kAmbiguousLimit, 0, 0);
  Tolerance open_tolerance = Tolerance::absolute(0.0);
  const Comparison open_result = compare_bounded(open, open_tolerance);
  results.push_back({"samples left open by rounding: " + std::to_string(ambiguous_total) + " of " +
                         std::to_string(samples_total) + " (<= 2 %)",
                     open_tolerance, open_result, true});
  return results;
}

}  // namespace pn
