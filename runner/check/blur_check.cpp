// Cases of the blur check: every fixture at every check size, for the paper's
// default (r 3), the identity (r 0), a narrow and a wide kernel, the
// depth-aware variant over a step-edge and a NaN/Inf-sprinkled depth, and the
// adaptive radius over seeded filter sides (lit, contact, every radius, large),
// plain and depth-aware; and the adaptive radius's radius-0 pixels, bit-exact.
// Two- and four-channel images (the moments of vsm.glsl), channel c holding
// fixture i + c, through the same code path, plain (r 3) and depth-aware,
// against the same direct 2-D convolution per channel, each channel under
// the tolerance of its own largest magnitude.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>

#include "check/blur_tolerance.h"
#include "check/module_check.h"
#include "core/integer_hash.h"
#include "fixture_images/texture_fixture.h"
#include "pass_runners/blur_pass.h"
#include "pcss_regions.h"  // PN_REGION_LIT
#include "reference/blur_reference.h"

namespace pn {
namespace {

constexpr std::uint32_t kFilterSideSeed = 0x5eed00b1u;

struct BlurCase {
  BlurParams params;
  const char* depth_fixture;  // depth-aware cases only
};

BlurParams adaptive(int radius, double sigma, bool depth_aware, float pixels_per_texel) {
  BlurParams p{radius, sigma, depth_aware, 0.05};
  p.adaptive = true;
  p.pixels_per_texel = pixels_per_texel;
  return p;
}

std::vector<BlurCase> default_cases() {
  return {
      {{3, 1.0, false, 0.0}, nullptr},   // seed 000 §5.3 defaults
      {{0, 1.0, false, 0.0}, nullptr},   // identity
      {{1, 0.5, false, 0.0}, nullptr},   // narrow
      {{7, 3.0, false, 0.0}, nullptr},   // wide, larger than the small fixtures
      {{3, 1.0, true, 0.05}, "step_edge"},
      {{3, 1.0, true, 0.05}, "nonfinite"},
      {adaptive(3, 1.0, false, 1.0f), nullptr},  // Fast PCSS's Step 6, screen = map
      {adaptive(3, 1.0, false, 0.5f), nullptr},  // a map finer than the screen
      {adaptive(7, 3.0, false, 2.5f), nullptr},  // wide, k not a power of two
      {adaptive(3, 1.0, true, 1.0f), "step_edge"},
      {adaptive(3, 1.0, true, 1.0f), "nonfinite"},
  };
}

std::string case_name(const char* fixture, int w, int h, const BlurCase& c) {
  char text[160];
  std::snprintf(text, sizeof text, "%s %dx%d r=%d sigma=%g", fixture, w, h, c.params.radius, c.params.sigma);
  std::string name = text;
  if (c.params.depth_aware)
    name += " depth-aware(" + std::string(c.depth_fixture) + ", tol " + std::to_string(c.params.depth_tolerance) + ")";
  if (c.params.adaptive) {
    std::snprintf(text, sizeof text, " adaptive(k %g)", c.params.pixels_per_texel);
    name += text;
  }
  return name;
}

// A filter-region map (d, x, y, s) whose sides s are seeded per pixel: lit
// (PN_REGION_LIT, NaN, -Inf), contact (s k < 2), exactly on a radius's
// boundary (s = 2j / k), anywhere in the range of radii 0..R+1, large, +Inf.
Image filter_sides(int width, int height, float k, int radius) {
  Image map(width, height, 4);
  const float range = static_cast<float>(2 * radius + 4) / k;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::uint32_t h = integer_hash(kFilterSideSeed ^ integer_hash(static_cast<std::uint32_t>(x) ^
                                                                          integer_hash(static_cast<std::uint32_t>(y))));
      const float u = static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
      float s = 0.0f;
      switch (h % 8) {
        case 0: s = static_cast<float>(PN_REGION_LIT); break;
        case 1: s = (h & 256) ? std::numeric_limits<float>::quiet_NaN() : -std::numeric_limits<float>::infinity(); break;
        case 2: s = u * 2.0f / k; break;                                        // contact
        case 3: s = static_cast<float>(2 * static_cast<int>(h % 37 % (radius + 2))) / k; break;  // a boundary
        case 4: case 5: s = u * range; break;                                   // every radius
        case 6: s = range + u * 1e4f; break;                                    // large
        default: s = (h & 256) ? std::numeric_limits<float>::infinity() : 1e30f; break;
      }
      map.at(x, y, 0) = 1.0f;
      map.at(x, y, 3) = s;
    }
  return map;
}

// Pixels of radius 0 keep their value exactly (contact shadows, lit pixels):
// both images are the source's value there (non-finite read as
// PN_BLUR_NONFINITE_VALUE) and 0 elsewhere.
CaseResult radius_zero_case(const std::string& name, const Image& source, const Image& observed,
                            const Image& map, const BlurParams& params) {
  Image expected(source.width, source.height), kept(source.width, source.height);
  int pixels = 0;
  for (int y = 0; y < source.height; ++y)
    for (int x = 0; x < source.width; ++x)
      if (blur_adaptive_radius(map.at(x, y, 3), params.pixels_per_texel, params.radius) == 0) {
        const float v = source.at(x, y);
        expected.at(x, y) = std::isfinite(v) ? v : kBlurNonfiniteValue;
        kept.at(x, y) = observed.at(x, y);
        ++pixels;
      }
  return {name + ": its " + std::to_string(pixels) + " pixels of radius 0 unchanged", Tolerance::exact(),
          compare(expected, kept, Tolerance::exact())};
}

// Channel c of image i: fixture (i + c) mod the fixture count, so every fixture (NaN/Inf too) is some channel.
Image multi_channel_source(size_t first, int width, int height, int channels) {
  constexpr size_t n = std::size(fixtures::kTextureFixtures);
  Image out(width, height, channels);
  for (int c = 0; c < channels; ++c) {
    const Image one = generate_fixture(fixtures::kTextureFixtures[(first + static_cast<size_t>(c)) % n], width, height);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) out.at(x, y, c) = one.at(x, y);
  }
  return out;
}

// The multi-channel cases: per channel, reference and tolerance as for one channel.
void multi_channel_cases(const CheckEnvironment& env, const BlurPass& pass, std::vector<CaseResult>& results) {
  const BlurCase cases[] = {{{3, 1.0, false, 0.0}, nullptr}, {{3, 1.0, true, 0.05}, "step_edge"}};
  for (int channels : {2, 4})
    for (const BlurCase& c : cases)
      for (size_t i = 0; i < std::size(fixtures::kTextureFixtures); ++i)
        for (const auto& size : fixtures::kCheckSizes) {
          const Image source = multi_channel_source(i, size.width, size.height, channels);
          const std::unique_ptr<DeviceTexture> source_texture = env.device.upload(source);
          Image depth;
          std::unique_ptr<DeviceTexture> depth_texture;
          if (c.params.depth_aware) {
            depth = generate_fixture(find_fixture(c.depth_fixture), size.width, size.height);
            depth_texture = env.device.upload(depth);
          }
          const std::unique_ptr<DeviceTexture> result =
              pass.run(*source_texture, depth_texture.get(), size.width, size.height, c.params, nullptr, channels);
          const Image observed = channels_of(env.device.read_texture(*result), 0, channels);
          const Image expected = c.params.depth_aware ? blur_depth_aware_reference(source, depth, c.params)
                                                      : blur_reference(source, c.params);
          for (int ch = 0; ch < channels; ++ch) {
            const Image one = channels_of(source, ch, 1);
            const Tolerance tolerance = blur_tolerance(c.params, one);
            const std::string name = case_name(fixtures::kTextureFixtures[(i + static_cast<size_t>(ch)) %
                                                                          std::size(fixtures::kTextureFixtures)].name,
                                               size.width, size.height, c) +
                                     " channel " + std::to_string(ch) + " of " + std::to_string(channels);
            results.push_back({name, tolerance,
                               compare(channels_of(expected, ch, 1), channels_of(observed, ch, 1), tolerance)});
          }
        }
}

}  // namespace

std::vector<CaseResult> run_blur_check(const CheckEnvironment& env) {
  std::vector<BlurCase> cases = default_cases();
  if (env.options.blur) {
    env.options.blur->validate();
    cases = {{*env.options.blur, env.options.blur->depth_aware ? "step_edge" : nullptr}};
  }
  const BlurPass pass(env.device, env.tree);
  std::vector<CaseResult> results;
  for (const BlurCase& c : cases) {
    for (const auto& fixture : fixtures::kTextureFixtures) {
      for (const auto& size : fixtures::kCheckSizes) {
        const Image source = generate_fixture(fixture, size.width, size.height);
        const std::unique_ptr<DeviceTexture> source_texture = env.device.upload(source);
        Image depth, map;
        std::unique_ptr<DeviceTexture> depth_texture, map_texture;
        if (c.params.depth_aware) {
          depth = generate_fixture(find_fixture(c.depth_fixture), size.width, size.height);
          depth_texture = env.device.upload(depth);
        }
        if (c.params.adaptive) {
          map = filter_sides(size.width, size.height, c.params.pixels_per_texel, c.params.radius);
          map_texture = env.device.upload(map);
        }
        const std::unique_ptr<DeviceTexture> result = pass.run(*source_texture, depth_texture.get(), size.width,
                                                               size.height, c.params, map_texture.get());
        const Image observed = env.device.read_texture(*result);
        const Image expected =
            c.params.adaptive      ? blur_adaptive_reference(source, map, c.params.depth_aware ? &depth : nullptr, c.params)
            : c.params.depth_aware ? blur_depth_aware_reference(source, depth, c.params)
                                   : blur_reference(source, c.params);
        const Tolerance tolerance = blur_tolerance(c.params, source);
        const std::string name = case_name(fixture.name, size.width, size.height, c);
        results.push_back({name, tolerance, compare(expected, observed, tolerance)});
        if (c.params.adaptive) results.push_back(radius_zero_case(name, source, observed, map, c.params));
      }
    }
  }
  if (!env.options.blur) multi_channel_cases(env, pass, results);
  return results;
}

}  // namespace pn
