// The traversal recursion on the CPU: exact at leaf 1, bounded by its budget.
#include <catch2/catch.hpp>

#include "fixture_images/texture_fixture.h"
#include "reference/depth_pyramid_reference.h"
#include "reference/traversal_reference.h"

TEST_CASE("at leaf side 1 the recursion equals brute force: counts exactly, blocker mean to rounding") {
  const pn::SampleTable table = pn::generate_sample_table(7);
  for (const auto& fixture : pn::fixtures::kTextureFixtures) {
    const pn::Image depth = pn::sanitized_depths(pn::generate_fixture(fixture, 40, 40));
    for (pn::Rect r : {pn::Rect{0, 0, 32, 32}, pn::Rect{3, 5, 17, 30}, pn::Rect{39, 0, 1, 40}, pn::Rect{8, 8, 1, 1}}) {
      for (float receiver : {0.0f, 0.3f, 0.5f, 0.7f, 2.0f}) {
        const auto brute = pn::brute_force_occluders(depth, r, receiver, 0.0f);
        const auto tree = pn::traversal_reference(depth, 5, table, r, {receiver, 0.0f, 1});
        INFO(fixture.name << " region " << r.x << "," << r.y << " " << r.width << "x" << r.height << " receiver " << receiver);
        CHECK(tree.occluders == brute.occluders);
        CHECK(tree.blocker_mean() == Approx(brute.blocker_mean()).epsilon(1e-12));
        CHECK(tree.texels == brute.texels);
      }
    }
  }
}

TEST_CASE("the bias moves the threshold: d occludes when d < dP - bias") {
  pn::Image depth(2, 2, 1, 0.5f);
  depth.at(1, 1) = 0.4f;
  const pn::Rect all{0, 0, 2, 2};
  CHECK(pn::brute_force_occluders(depth, all, 0.5f, 0.0f).occluders == 1);
  CHECK(pn::brute_force_occluders(depth, all, 0.5f, 0.1f).occluders == 0);  // 0.4 < 0.4 is false
  CHECK(pn::brute_force_occluders(depth, all, 0.6f, 0.0f).occluders == 4);
}

TEST_CASE("a node budget bounds the nodes visited by budget + 3 per level + 1, and nothing is dropped") {
  const pn::Image depth = pn::sanitized_depths(pn::generate_fixture(pn::find_fixture("fine_checker"), 64, 64));
  const pn::SampleTable table = pn::generate_sample_table(7);
  const pn::Rect r{0, 0, 64, 64};
  const auto full = pn::traversal_reference(depth, 6, table, r, {0.5f, 0.0f, 1});
  CHECK(full.nodes == (4 * 4096 - 1) / 3);  // every node of the 6-level tree
  for (int budget : {1, 10, 100, 1000}) {
    pn::TraversalParams p{0.5f, 0.0f, 1};
    p.node_budget = budget;
    const auto limited = pn::traversal_reference(depth, 6, table, r, p);
    INFO("budget " << budget);
    CHECK(limited.nodes <= budget + 3 * 6 + 1);
    CHECK(limited.occluders > 0);  // estimated, not dropped: the checker is half occluders
    CHECK(limited.occluded_fraction() == Approx(0.5).margin(0.5));
  }
}
