// The Poisson PCSS reference on hand-worked disks, and the constants and the
// constant disk that C++ and GLSL share.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "pass_runners/poisson_pcss_pass.h"
#include "poisson_pcss.h"
#include "reference/poisson_pcss_reference.h"
#include "sampling/poisson_disk.h"
#include "sampling/poisson_disk_source.h"

namespace {

// d(x, y) = 0.1 (x + 4 y) on a 4×4 map.
pn::Image ramp_map() {
  pn::Image m(4, 4, 1);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) m.at(x, y) = 0.1f * static_cast<float>(x + 4 * y);
  return m;
}

const std::vector<pn::Sample> kCross{{0, 0}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}};

}  // namespace

TEST_CASE("Poisson reference: a cross of 5 samples of diameter 2 at (2.5, 2.5) reads texels (2,2) (3,2) (2,3) (1,2) (2,1)") {
  // Depths 1.0, 1.1, 1.4, 0.9, 0.6: below 1.05 are 1.0, 0.9 and 0.6.
  const auto s = pn::poisson_pcss_reference(ramp_map(), kCross, {2.5, 2.5, 2.0, 1.05, 0.0, 5});
  CHECK(s.samples == 5);
  CHECK(s.occluders == 3);
  CHECK(s.depth_sum == Approx(2.5).epsilon(1e-6));
  CHECK(s.occluded_fraction() == Approx(0.6));
  CHECK(s.blocker_mean() == Approx(2.5 / 3.0).epsilon(1e-6));
  // The bias moves the threshold to 0.95: 0.9 and 0.6 remain.
  CHECK(pn::poisson_pcss_reference(ramp_map(), kCross, {2.5, 2.5, 2.0, 1.05, 0.1, 5}).occluders == 2);
  // A depth equal to dP - bias does not occlude: 1.0 is not below 1.0.
  CHECK(pn::poisson_pcss_reference(ramp_map(), {{0, 0}}, {2.5, 2.5, 2.0, 1.0f, 0.0, 1}).occluders == 0);
}

TEST_CASE("Poisson reference: rotation (cos, sin) turns the offsets counter-clockwise in texel axes") {
  const std::vector<pn::Sample> right{{1, 0}};
  const pn::Image m = ramp_map();
  // (1, 0) turned by 90 degrees is (0, 1): (2.5, 3.5) -> texel (2, 3), depth 1.4.
  const pn::PoissonPcssQuery q90{2.5, 2.5, 2.0, 9.0, 0.0, 1, 0.0, 1.0};
  CHECK(pn::poisson_pcss_reference(m, right, q90).depth_sum == Approx(1.4).epsilon(1e-6));
  // By 180 degrees: (-1, 0): texel (1, 2), depth 0.9.
  const pn::PoissonPcssQuery q180{2.5, 2.5, 2.0, 9.0, 0.0, 1, -1.0, 0.0};
  CHECK(pn::poisson_pcss_reference(m, right, q180).depth_sum == Approx(0.9).epsilon(1e-6));
  const auto p = pn::poisson_pcss_position({1.0, 2.0, 4.0, 0.0, 0.0, 1, 0.6, 0.8}, {1.0f, 0.0f});
  CHECK(p.x == Approx(2.2));  // 1 + 2 * 0.6
  CHECK(p.y == Approx(3.6));  // 2 + 2 * 0.8
}

TEST_CASE("Poisson reference: samples outside the map count as samples and occlude nothing") {
  const pn::Image m = ramp_map();
  // At (0.5, 0.5) with diameter 2: (-0.5, 0.5) and (0.5, -0.5) are outside; (0,0) (1,0) (0,1) read 0, 0.1, 0.4.
  const auto s = pn::poisson_pcss_reference(m, kCross, {0.5, 0.5, 2.0, 9.0, 0.0, 5});
  CHECK(s.samples == 5);
  CHECK(s.occluders == 3);
  CHECK(s.depth_sum == Approx(0.5).epsilon(1e-6));
  // A position of exactly N is outside; exactly 3.0 reads texel 3.
  CHECK(pn::poisson_pcss_reference(m, {{1, 0}}, {3.0, 0.5, 2.0, 9.0, 0.0, 1}).occluders == 0);    // x = 4
  CHECK(pn::poisson_pcss_reference(m, {{1, 0}}, {2.0, 0.5, 2.0, 9.0, 0.0, 1}).depth_sum == Approx(0.3));  // x = 3
  // A non-finite centre puts every sample outside.
  CHECK(pn::poisson_pcss_reference(m, kCross, {NAN, 1.0, 2.0, 9.0, 0.0, 5}).occluders == 0);
  CHECK(pn::poisson_pcss_reference(m, kCross, {INFINITY, 1.0, 2.0, 9.0, 0.0, 5}).samples == 5);
}

TEST_CASE("Poisson reference: diameter 0 reads the centre's texel with every sample; counts are clamped") {
  const pn::Image m = ramp_map();
  const auto hard = pn::poisson_pcss_reference(m, kCross, {1.7, 2.2, 0.0, 9.0, 0.0, 5});  // texel (1, 2): 0.9
  CHECK(hard.occluders == 5);
  CHECK(hard.depth_sum == Approx(4.5).epsilon(1e-6));
  CHECK(pn::poisson_pcss_reference(m, kCross, {1.7, 2.2, 0.0, 9.0, 0.0, 50}).samples == 5);
  CHECK(pn::poisson_pcss_reference(m, kCross, {1.7, 2.2, 0.0, 9.0, 0.0, -2}).samples == 0);
  CHECK(pn::poisson_pcss_reference(m, kCross, {1.7, 2.2, 0.0, 9.0, 0.0, 2}).samples == 2);
}

TEST_CASE("Poisson reference: NaN and +-Inf texels never occlude, and the sum stays finite") {
  pn::Image m(3, 1, 1);
  m.at(0, 0) = NAN, m.at(1, 0) = -INFINITY, m.at(2, 0) = INFINITY;
  const std::vector<pn::Sample> row{{-2.0f / 3.0f, 0}, {0, 0}, {2.0f / 3.0f, 0}};
  const auto s = pn::poisson_pcss_reference(m, row, {1.5, 0.5, 3.0, INFINITY, 0.0, 3});
  CHECK(s.samples == 3);
  CHECK(s.occluders == 0);
  CHECK(s.depth_sum == 0.0);
}

TEST_CASE("poisson_pcss.h: one maximum for GLSL and C++, and the default counts of seeds 002 / 004") {
  STATIC_REQUIRE(PN_POISSON_MAX_SAMPLES == 64);
  STATIC_REQUIRE(PN_POISSON_BLOCKER_SAMPLES == 36);
  STATIC_REQUIRE(PN_POISSON_PCF_SAMPLES == 64);
  STATIC_REQUIRE(PN_POISSON_BLOCKER_SAMPLES <= PN_POISSON_MAX_SAMPLES);
}

TEST_CASE("exports/poisson_disks.glsl holds `penumbra poisson` of the runner's two disks verbatim") {
  std::ifstream in(std::string(PENUMBRA_GLSL_DIR) + "/exports/poisson_disks.glsl");
  std::stringstream text;
  text << in.rdbuf();
  const std::string blocker = pn::poisson_disk_glsl(
      pn::poisson_disk(PN_POISSON_BLOCKER_SAMPLES, pn::kPoissonBlockerDiskSeed), "PN_EXPORT_BLOCKER_DISK",
      pn::kPoissonBlockerDiskSeed);
  const std::string filter = pn::poisson_disk_glsl(pn::poisson_disk(PN_POISSON_PCF_SAMPLES, pn::kPoissonFilterDiskSeed),
                                                   "PN_EXPORT_FILTER_DISK", pn::kPoissonFilterDiskSeed);
  CHECK(text.str().find(blocker) != std::string::npos);
  CHECK(text.str().find(filter) != std::string::npos);
}

TEST_CASE("poisson_pcss_query.comp holds `penumbra poisson --count 16 --seed 1`'s output verbatim") {
  std::ifstream in(std::string(PENUMBRA_GLSL_DIR) + "/passes/poisson_pcss_query.comp");
  std::stringstream text;
  text << in.rdbuf();
  const std::string disk = pn::poisson_disk_glsl(pn::poisson_disk(pn::kPoissonQueryConstCount, pn::kPoissonQueryConstSeed),
                                                 "PN_POISSON_DISK", pn::kPoissonQueryConstSeed);
  CHECK(text.str().find(disk) != std::string::npos);
}
