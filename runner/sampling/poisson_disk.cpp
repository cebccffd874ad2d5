#include "sampling/poisson_disk.h"

#include <cmath>

#include "core/error.h"
#include "core/seeded_random.h"

namespace pn {

PoissonDisk bridson_disk(double r, std::uint32_t seed, int candidates) {
  SeededRandom random(seed);
  // Background grid of cell r/√2 over [-1, 1]²: at most one point per cell.
  const double cell = r / std::sqrt(2.0);
  const int cells = static_cast<int>(std::ceil(2.0 / cell));
  std::vector<int> grid(static_cast<size_t>(cells) * cells, -1);
  const auto cell_of = [&](double v) { return std::min(cells - 1, std::max(0, static_cast<int>((v + 1.0) / cell))); };
  PoissonDisk disk;
  disk.min_distance = r;
  std::vector<int> active;
  const auto fits = [&](double x, double y) {
    if (x * x + y * y > 1.0) return false;
    const int cx = cell_of(x), cy = cell_of(y);
    for (int j = std::max(0, cy - 2); j <= std::min(cells - 1, cy + 2); ++j)
      for (int i = std::max(0, cx - 2); i <= std::min(cells - 1, cx + 2); ++i) {
        const int k = grid[static_cast<size_t>(j) * cells + i];
        if (k < 0) continue;
        const double dx = disk.points[static_cast<size_t>(k)].x - x, dy = disk.points[static_cast<size_t>(k)].y - y;
        if (dx * dx + dy * dy < r * r) return false;
      }
    return true;
  };
  const auto add = [&](double x, double y) {
    grid[static_cast<size_t>(cell_of(y)) * cells + cell_of(x)] = static_cast<int>(disk.points.size());
    active.push_back(static_cast<int>(disk.points.size()));
    disk.points.push_back({static_cast<float>(x), static_cast<float>(y)});
  };
  // First point: uniform in the disk (by rejection).
  for (;;) {
    const double x = random.uniform_float(-1.0f, 1.0f), y = random.uniform_float(-1.0f, 1.0f);
    if (x * x + y * y <= 1.0) {
      add(x, y);
      break;
    }
  }
  while (!active.empty()) {
    const size_t pick = static_cast<size_t>(random.uniform_int(0, static_cast<int>(active.size()) - 1));
    const Sample centre = disk.points[static_cast<size_t>(active[pick])];
    bool placed = false;
    for (int c = 0; c < candidates && !placed; ++c) {
      // Uniform in the annulus [r, 2r] around the active point.
      const double angle = random.uniform_float(0.0f, 6.2831853f);
      const double radius = r * std::sqrt(1.0 + 3.0 * random.uniform_float(0.0f, 1.0f));
      const double x = centre.x + radius * std::cos(angle), y = centre.y + radius * std::sin(angle);
      if (fits(x, y)) add(x, y), placed = true;
    }
    if (!placed) active.erase(active.begin() + static_cast<std::ptrdiff_t>(pick));
  }
  return disk;
}

PoissonDisk poisson_disk(int count, std::uint32_t seed) {
  if (count < 1 || count > 4096)
    throw Error("Poisson disk of " + std::to_string(count) + " samples: expected 1 to 4096");
  // Shrink r until some run gives `count` points exactly (so that none is cut
  // and the disk stays evenly covered); 16 runs per r, seeds drawn from `seed`.
  SeededRandom seeds(seed);
  for (double r = 2.0 / std::sqrt(static_cast<double>(count));; r *= 0.98) {
    PoissonDisk closest;
    for (int run = 0; run < 16; ++run) {
      PoissonDisk disk = bridson_disk(r, static_cast<std::uint32_t>(seeds.uniform_int(0, 0x7fffffff)));
      if (static_cast<int>(disk.points.size()) == count) return disk;
      if (static_cast<int>(disk.points.size()) > count &&
          (closest.points.empty() || disk.points.size() < closest.points.size()))
        closest = std::move(disk);
    }
    if (!closest.points.empty()) {  // every run overshot: keep the first `count` of the closest
      closest.points.resize(static_cast<size_t>(count));
      return closest;
    }
  }
}

}  // namespace pn
