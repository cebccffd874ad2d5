// Cases of the physical_reference check: each scene's GPU physical reference
// (hard shadows from 4x4 light sample points, averaged) against its CPU
// definition (scene/visibility_reference.h: segment tests to every sample
// point). The raster answers each sample point through a shadow-map texel, so
// the rule (docs/physical_reference.md) is, per pixel, one of:
//   - within one sample (1/16) of the exact fraction;
//   - within the range that nearest-texel lookups of the ray-cast shadow maps
//     allow (visibility_reference's lowest..highest), one sample wider;
//   - on a camera edge (its 3x3 neighbours see another box, or nothing): within
//     the exact fractions of its 3x3 neighbourhood, one sample wider.
// One sample of slack everywhere: a tie the CPU cannot predict — a texel
// centre on an occluder's edge, where the rasteriser's fixed-point edge test
// and the ray disagree, or a receiver depth within float rounding of the
// occluder's plus the bias — flips one sample point of a pixel.
#include <cmath>
#include <string>

#include "check/module_check.h"
#include "check/raster_compare.h"
#include "gl/texture.h"
#include "passes/physical_reference_pass.h"
#include "scene/scene.h"
#include "scene/visibility_reference.h"

namespace pn {
namespace {

constexpr int kMapSize = 128, kScreen = 64, kSamplesPerSide = 4;
constexpr float kBias = 0.02f;  // linear depth units: far above float rounding of depths <= 40

bool on_camera_edge(const Image& box, int x, int y) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if (nx >= 0 && nx < box.width && ny >= 0 && ny < box.height && box.at(nx, ny) != box.at(x, y)) return true;
    }
  return false;
}

}  // namespace

std::vector<CaseResult> run_physical_reference_check(const CheckEnvironment& env) {
  const PhysicalReferenceRenderer renderer(env.context, env.tree);
  const double one_sample = 1.0 / (kSamplesPerSide * kSamplesPerSide) + 1e-6;  // + float rounding of k / n
  std::vector<CaseResult> results;
  for (const auto& fixture : fixtures::kScenes) {
    const Scene scene = make_scene(fixture, kMapSize);
    const VisibilityReference reference = visibility_reference(scene, kScreen, kSamplesPerSide, kBias);
    const Image observed = read_float_texture(
        env.context, renderer.render(scene, kScreen, kSamplesPerSide, kBias), kScreen, kScreen, 1);
    const SilhouetteRule neighbours = within_neighbour_range(reference.fraction, observed, one_sample);
    const SilhouetteRule explained = [&](int x, int y) {
      const double o = observed.at(x, y);
      return (o >= reference.lowest.at(x, y) - one_sample && o <= reference.highest.at(x, y) + one_sample) ||
             (on_camera_edge(reference.box, x, y) && neighbours(x, y));
    };
    const std::string name = std::string(fixture.name) + " " + std::to_string(kScreen) + "x" +
                             std::to_string(kScreen) + ", map " + std::to_string(kMapSize) + ", " +
                             std::to_string(kSamplesPerSide * kSamplesPerSide) + " light samples: visible fraction";
    for (CaseResult& c : compare_raster(name + " vs segment tests", reference.fraction, observed, one_sample,
                                        explained, "lies within its texel range, or on a camera edge its 3x3 range"))
      results.push_back(std::move(c));
    // The rule's case says where; this one says what: the exact and observed fractions of unexplained pixels.
    Image exact_there(kScreen, kScreen), observed_there(kScreen, kScreen);
    for (int y = 0; y < kScreen; ++y)
      for (int x = 0; x < kScreen; ++x)
        if (std::fabs(reference.fraction.at(x, y) - observed.at(x, y)) > one_sample && !explained(x, y))
          exact_there.at(x, y) = reference.fraction.at(x, y), observed_there.at(x, y) = observed.at(x, y);
    results.push_back({name + " at unexplained pixels: exact vs observed", Tolerance::exact(),
                       compare(exact_there, observed_there, Tolerance::exact())});
  }
  return results;
}

}  // namespace pn
