// The frontier bench's two computations without GL, against independent
// definitions: the Pareto marks (mark_frontier compares every pair) against
// a sweep by time keeping the running minimum of MAE, and the fetch proxy
// (fetch_proxy walks tiles) against a per-pixel scan of each pixel's tile.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "bench/frontier_bench.h"
#include "frame/fetch_proxy.h"

TEST_CASE("frontier: the Pareto marks equal a sweep by time with the running minimum of MAE") {
  std::mt19937 random(25);
  for (int trial = 0; trial < 200; ++trial) {
    pn::FrontierPoint p;
    const int n = 1 + static_cast<int>(random() % 12);
    for (int i = 0; i < n; ++i) {
      pn::FrontierRow r;
      r.technique = i == 0 ? "fast" : "m" + std::to_string(i);
      r.family = i == 0 ? "fast" : (i % 2 ? "poisson" : "fast");
      r.ms = static_cast<double>(random() % 8);  // ties on purpose
      r.mae = static_cast<double>(random() % 8);
      p.rows.push_back(r);
    }
    pn::mark_frontier(p);
    // Sweep: by time, then MAE; a row is on the frontier when its MAE is below every faster row's,
    // and no row of the same time has a smaller MAE; equal (time, MAE) pairs share the verdict.
    std::vector<pn::FrontierRow> sorted = p.rows;
    std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return std::tie(a.ms, a.mae) < std::tie(b.ms, b.mae); });
    for (const pn::FrontierRow& r : p.rows) {
      double best_before = INFINITY;
      for (const pn::FrontierRow& o : sorted)
        if (o.ms < r.ms || (o.ms == r.ms && o.mae < r.mae)) best_before = std::min(best_before, o.mae);
      INFO("trial " << trial << " row " << r.technique << " (" << r.ms << ", " << r.mae << ")");
      CHECK(r.on_frontier == (r.mae < best_before));
    }
    // The default's challenger: the fastest row of another family at most as far from the truth.
    const pn::FrontierRow& fast = p.rows.front();
    const pn::FrontierRow* best = nullptr;
    for (const pn::FrontierRow& o : sorted)
      if (o.family != "fast" && o.mae <= fast.mae && o.ms < fast.ms && (!best || o.ms < best->ms)) best = &o;
    REQUIRE(p.beats_default.has_value() == (best != nullptr));
    if (best) CHECK(p.beats_default->ms == best->ms);
  }
}

TEST_CASE("fetch proxy: the mean over receivers, and each receiver charged its 8x8 tile's maximum") {
  std::mt19937 random(8);
  for (const auto& [w, h] : {std::pair{16, 16}, {13, 21}, {1, 1}, {64, 8}}) {
    pn::Image fetches(w, h), mask(w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) fetches.at(x, y) = static_cast<float>(random() % 100), mask.at(x, y) = random() % 3 ? 1.0f : 0.0f;
    const auto receiver = [&](int x, int y) { return mask.at(x, y) != 0.0f; };
    double sum = 0.0, charged = 0.0;
    long n = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (!receiver(x, y)) continue;
        double most = 0.0;  // over the receivers of (x, y)'s tile
        for (int v = y / 8 * 8; v < std::min(h, y / 8 * 8 + 8); ++v)
          for (int u = x / 8 * 8; u < std::min(w, x / 8 * 8 + 8); ++u)
            if (receiver(u, v)) most = std::max(most, static_cast<double>(fetches.at(u, v)));
        sum += fetches.at(x, y), charged += most, ++n;
      }
    const pn::FetchProxy p = pn::fetch_proxy(fetches, receiver);
    INFO(w << "x" << h);
    CHECK(p.per_receiver == Approx(n ? sum / n : 0.0).epsilon(1e-12));
    CHECK(p.tile_max == Approx(n ? charged / n : 0.0).epsilon(1e-12));
    CHECK(p.tile_max >= p.per_receiver);
  }
}
