#include "sampling/poisson_disk.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <regex>
#include <set>

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

namespace {

// GLSL 4.50 §3.6 (and ES 3.10 §3.7): keywords and reserved words — a name the compiler refuses.
bool glsl_keyword_or_reserved(const std::string& name) {
  static const std::set<std::string> words{
      // keywords
      "const", "uniform", "buffer", "shared", "attribute", "varying", "coherent", "volatile", "restrict", "readonly",
      "writeonly", "atomic_uint", "layout", "centroid", "flat", "smooth", "noperspective", "patch", "sample",
      "invariant", "precise", "break", "continue", "do", "for", "while", "switch", "case", "default", "if", "else",
      "subroutine", "in", "out", "inout", "int", "void", "bool", "true", "false", "float", "double", "discard",
      "return", "uint", "lowp", "mediump", "highp", "precision", "struct",
      // reserved for future use
      "common", "partition", "active", "asm", "class", "union", "enum", "typedef", "template", "this", "resource",
      "goto", "inline", "noinline", "public", "static", "extern", "external", "interface", "long", "short", "half",
      "fixed", "unsigned", "superp", "input", "output", "filter", "sizeof", "cast", "namespace", "using"};
  if (words.count(name)) return true;
  // The type families: vectors (vec3, ivec2, hvec4, ...), matrices (mat3, dmat2x4), samplers and images.
  static const std::regex types("[ibudhf]?vec[234]|d?mat[234](x[234])?|[iu]?(sampler|image|texture)[0-9A-Z].*");
  return std::regex_match(name, types);
}

}  // namespace

std::string poisson_disk_glsl(const PoissonDisk& disk, const std::string& name, std::uint32_t seed) {
  // A GLSL identifier (GLSL ES 3.10 §3.7): a letter or _, then letters, digits and _; names
  // beginning with gl_ or holding __ are reserved; at most 1024 characters.
  bool identifier = !name.empty() && name.size() <= 1024 && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                    name.rfind("gl_", 0) != 0 && name.find("__") == std::string::npos;
  for (char c : name) identifier = identifier && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  if (!identifier)
    throw Error("Poisson disk name '" + name + "': expected a GLSL identifier (letters, digits and _, not starting with "
                "a digit or gl_, no __)");
  if (glsl_keyword_or_reserved(name))
    throw Error("Poisson disk name '" + name + "': a GLSL keyword or reserved word: expected another identifier");
  char line[96];
  std::snprintf(line, sizeof line, "// %zu Poisson-disk samples in the unit disk, minimum distance %.6f,\n",
                disk.points.size(), disk.min_distance);
  std::string out = line;
  std::snprintf(line, sizeof line, "// Bridson's algorithm, seed %u (penumbra poisson).\n", seed);
  out += line;
  out += "const vec2 " + name + "[" + std::to_string(disk.points.size()) + "] = vec2[](\n";
  for (size_t i = 0; i < disk.points.size(); ++i) {
    std::snprintf(line, sizeof line, "    vec2(%.9g, %.9g)%s\n", disk.points[i].x, disk.points[i].y,
                  i + 1 < disk.points.size() ? "," : "");
    out += line;
  }
  return out + ");\n";
}

}  // namespace pn
