#include "figures/figures.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "core/error.h"
#include "core/query_grid.h"
#include "core/write_file.h"
#include "draw/canvas.h"
#include "fixture_images/texture_fixture.h"
#include "gl/texture.h"
#include "pass_runners/blur_pass.h"
#include "pass_runners/depth_pyramid_pass.h"
#include "pass_runners/region_pass.h"
#include "pass_runners/reuse_pass.h"
#include "pass_runners/traversal_pass.h"
#include "reference/region_reference.h"

namespace fs = std::filesystem;

namespace pn {
namespace {

constexpr Rgb kPaper{255, 255, 255};
constexpr Rgb kMagenta{220, 0, 180};  // NaN / ±Inf texels
constexpr Rgb kRed{220, 40, 40};
constexpr Rgb kBlue{40, 90, 220};
constexpr Rgb kGreen{30, 160, 60};
constexpr Rgb kGrid{225, 225, 225};

// Source, blur (r 3, sigma 1), depth-aware blur over a step-edge depth — a checker with NaN/Inf sprinkled in.
Canvas blur_figure(const Context& context, const SourceTree& tree) {
  const int n = 48, scale = 5, gap = 12;
  Image source = generate_fixture(find_fixture("checker"), n, n);
  const Image holes = generate_fixture(find_fixture("nonfinite"), n, n);
  for (size_t i = 0; i < source.texels.size(); ++i)
    if (!std::isfinite(holes.texels[i])) source.texels[i] = holes.texels[i];
  const Image depth = generate_fixture(find_fixture("step_edge"), n, n);
  const BlurPass pass(context, tree);
  const std::unique_ptr<DeviceTexture> src = context.upload(source), dep = context.upload(depth);
  const Image plain = context.read_texture(*pass.run(*src, nullptr, n, n, {3, 1.0, false, 0.0}), 0, 0);
  const Image aware = context.read_texture(*pass.run(*src, dep.get(), n, n, {3, 1.0, true, 0.05}), 0, 0);
  Canvas canvas(3 * n * scale + 4 * gap, n * scale + 2 * gap, kPaper);
  int x = gap;
  for (const Image* image : {&std::as_const(source), &plain, &aware}) {
    canvas.grey(*image, 0, x, gap, scale, 0.0f, 1.0f, kMagenta);
    x += n * scale + gap;
  }
  return canvas;
}

// Levels 0, 2, 4, 6 of a boxes shadow map: min (top row) and max (bottom row), each at its true size.
Canvas pyramid_figure(const Context& context, const SourceTree& tree) {
  const int n = 128, scale = 2, gap = 10;
  const int levels[] = {0, 2, 4, 6};
  const Image map = generate_fixture(find_fixture("boxes"), n, n);
  const DepthPyramidBuilder builder(context, tree);
  const DepthPyramid pyramid = builder.build(*context.upload(map), n, n, 31);
  Canvas canvas(4 * n * scale + 5 * gap, 2 * n * scale + 3 * gap, kPaper);
  for (int i = 0; i < 4; ++i) {
    const Image level = read_pyramid_level(context, pyramid, levels[i]);
    const int x = gap + i * (n * scale + gap);
    canvas.outline(x - 1, gap - 1, n * scale + 2, n * scale + 2, kGrid);
    canvas.outline(x - 1, 2 * gap + n * scale - 1, n * scale + 2, n * scale + 2, kGrid);
    canvas.grey(level, 0, x, gap, scale, 0.2f, 1.0f, kMagenta);
    canvas.grey(level, 1, x, 2 * gap + n * scale, scale, 0.2f, 1.0f, kMagenta);
  }
  return canvas;
}

// A 32×32 map: requested regions (red outline), the literal window (blue fill)
// and the centred option's window (green outline).
Canvas region_figure(const Context& context, const SourceTree& tree) {
  const int n = 32, scale = 16, margin = 3 * scale;
  const std::vector<Query> regions{{6.5f, 7.0f, 5.0f, 0}, {21.0f, 8.0f, 9.0f, 0}, {29.0f, 27.0f, 7.0f, 0},
                                   {5.0f, 25.0f, 11.0f, 0}, {16.0f, 18.0f, 3.0f, 0}};
  const RegionQuery pass(context, tree);
  const Image input = query_image(regions);
  const Image literal = pass.run(input, n, false), centred = pass.run(input, n, true);
  Canvas canvas(n * scale + 2 * margin, n * scale + 2 * margin, kPaper);
  for (int i = 0; i <= n; ++i) {
    canvas.fill(margin + i * scale, margin, 1, n * scale + 1, kGrid);
    canvas.fill(margin, margin + i * scale, n * scale + 1, 1, kGrid);
  }
  canvas.outline(margin, margin, n * scale + 1, n * scale + 1, {120, 120, 120});
  for (size_t k = 0; k < regions.size(); ++k) {
    const int x = static_cast<int>(k) % input.width, y = static_cast<int>(k) / input.width;
    const int side = static_cast<int>(literal.at(x, y, 2)) * scale;
    canvas.fill(margin + static_cast<int>(literal.at(x, y, 0)) * scale, margin + static_cast<int>(literal.at(x, y, 1)) * scale,
                side, side, kBlue, 0.3f);
    canvas.outline(margin + static_cast<int>(centred.at(x, y, 0)) * scale,
                   margin + static_cast<int>(centred.at(x, y, 1)) * scale, side, side, kGreen, 2);
    // The requested region: centre (x, y) in texel units, the texel centre of texel i at i + 0.5.
    const float half = regions[k][2] * 0.5f;
    const int rx = margin + static_cast<int>(std::lround((regions[k][0] - half) * scale));
    const int ry = margin + static_cast<int>(std::lround((regions[k][1] - half) * scale));
    const int rs = static_cast<int>(std::lround(regions[k][2] * scale));
    canvas.outline(rx, ry, rs, rs, kRed, 2);
  }
  return canvas;
}

// The table: one row per group (1, 4, 16 samples), one column per set; the
// n×n cells of each group are drawn, and every cell holds one sample.
Canvas sample_table_figure() {
  const SampleTable table = generate_sample_table(kSampleTableSeed);
  const int box = 96, gap = 12;
  Canvas canvas(SampleTable::kSets * box + (SampleTable::kSets + 1) * gap, 3 * box + 4 * gap, kPaper);
  int row = 0;
  for (auto [n, first] : {std::pair{1, 0}, std::pair{2, 1}, std::pair{4, 5}}) {
    for (int set = 0; set < SampleTable::kSets; ++set) {
      const int x0 = gap + set * (box + gap), y0 = gap + row * (box + gap);
      for (int i = 1; i < n * n; ++i) {  // thin strata, faint
        canvas.fill(x0 + i * box / (n * n), y0, 1, box, {240, 240, 240});
        canvas.fill(x0, y0 + i * box / (n * n), box, 1, {240, 240, 240});
      }
      for (int i = 1; i < n; ++i) {  // cells
        canvas.fill(x0 + i * box / n, y0, 1, box, {170, 170, 170});
        canvas.fill(x0, y0 + i * box / n, box, 1, {170, 170, 170});
      }
      canvas.outline(x0, y0, box + 1, box + 1, {90, 90, 90});
      for (int i = 0; i < n * n; ++i) {
        const Sample& q = table.at(first + i, set);
        canvas.fill(x0 + static_cast<int>(q.x * box) - 2, y0 + static_cast<int>(q.y * box) - 2, 5, 5, kBlue);
      }
    }
    ++row;
  }
  return canvas;
}

// Nodes visited per receiver (one receiver per texel of a 256² boxes map, on
// the ground, search region 32, bias 0.03 so that the sloped ground does not
// shadow itself): leaf 1 (exact) and leaf 8 (sampled), beside the map.
Canvas traversal_figure(const Context& context, const SourceTree& tree) {
  const int n = 256, gap = 10;
  const Image map = generate_fixture(find_fixture("boxes"), n, n);
  const DepthPyramid pyramid = DepthPyramidBuilder(context, tree).build(*context.upload(map), n, n, 31);
  const std::unique_ptr<DeviceTexture> table = upload_sample_table(context, generate_sample_table(kSampleTableSeed));
  const auto& boxes = find_fixture("boxes");
  std::vector<TraversalQuery> queries;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float ground = boxes_ground_depth(boxes, static_cast<float>(y), n);
      const RegionWindow w = region_reference(x + 0.5f, y + 0.5f, 32.0f, n);
      queries.push_back({{w.u, w.v, w.side, w.side}, ground + 0.002f, x, y});
    }
  const TraversalPass pass(context, tree);
  const TraversalBatch batch(context, queries);
  Canvas canvas(3 * n + 4 * gap, n + 2 * gap, kPaper);
  canvas.grey(map, 0, gap, gap, 1, 0.2f, 1.0f, kMagenta);
  int column = 1;
  for (int leaf : {1, 8}) {
    TraversalSettings settings;
    settings.leaf_side = leaf;
    settings.bias = 0.03f;
    pass.dispatch(pyramid, *table, batch, settings);
    const std::vector<TraversalReadback> results = batch.read();
    long most = 1;
    for (const auto& r : results) most = std::max(most, r.nodes);
    for (int k = 0; k < n * n; ++k) {
      const float share = static_cast<float>(results[static_cast<size_t>(k)].nodes) / static_cast<float>(most);
      canvas.fill(gap + column * (n + gap) + k % n, gap + k / n, 1, 1, node_heat(share));
    }
    ++column;
  }
  return canvas;
}

// Reuse groups on a 64×64 search-region-like map, k = 4 (Step 4) and k = 2
// (Step 5): every group in one colour, representatives marked, tile grid in white.
Canvas reuse_figure(const Context& context, const SourceTree& tree) {
  const int n = 64, scale = 6, gap = 12;
  Image entries(n, n, 4);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      entries.at(x, y, 0) = std::round((0.5f + 0.3f * std::sin(x / 9.0f) * std::cos(y / 6.0f)) * 30.0f) / 30.0f;
      entries.at(x, y, 1) = std::floor((x + 0.5f) * 0.75f) + 0.5f + 20.0f;
      entries.at(x, y, 2) = std::floor((y + 0.5f) * 0.75f) + 0.5f + 20.0f;
      entries.at(x, y, 3) = std::exp2(std::round(3.0f + std::sin((x - y) / 15.0f)));
    }
  const ReusePass pass(context, tree);
  const std::unique_ptr<DeviceTexture> entry_texture = context.upload(entries);
  const std::unique_ptr<DeviceTexture> values = context.make_texture(float_shape(n, n, 1));
  Canvas canvas(2 * n * scale + 3 * gap, n * scale + 2 * gap, kPaper);
  int column = 0;
  for (int tile : {4, 2}) {
    const std::unique_ptr<DeviceTexture> parents = pass.link(*entry_texture, n, n, {0.0f, 0.1f, 0.1f, tile});
    const Image groups = context.read_texture(*pass.gather(*parents, *values, n, n, tile), 0, 0);
    const int x0 = gap + column * (n * scale + gap);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const auto rx = static_cast<std::uint32_t>(groups.at(x, y, 0)), ry = static_cast<std::uint32_t>(groups.at(x, y, 1));
        std::uint32_t h = (rx * 73856093u) ^ (ry * 19349663u);
        h ^= h >> 13, h *= 0x5bd1e995u, h ^= h >> 15;
        const Rgb colour{static_cast<unsigned char>(80 + (h & 0x7f)), static_cast<unsigned char>(80 + ((h >> 8) & 0x7f)),
                         static_cast<unsigned char>(80 + ((h >> 16) & 0x7f))};
        canvas.fill(x0 + x * scale, gap + y * scale, scale, scale, colour);
        if (rx == static_cast<std::uint32_t>(x) && ry == static_cast<std::uint32_t>(y))
          canvas.fill(x0 + x * scale + 2, gap + y * scale + 2, 2, 2, {20, 20, 20});
      }
    for (int i = 0; i <= n; i += tile) {
      canvas.fill(x0 + i * scale, gap, 1, n * scale, kPaper);
      canvas.fill(x0, gap + i * scale, n * scale, 1, kPaper);
    }
    ++column;
  }
  return canvas;
}

}  // namespace

Rgb node_heat(float share) {
  const float t = std::sqrt(share);
  return {static_cast<unsigned char>(255 * std::min(1.0f, 1.6f * t)),
          static_cast<unsigned char>(255 * std::clamp(1.6f * t - 0.6f, 0.0f, 1.0f)),
          static_cast<unsigned char>(255 * std::clamp(3.0f * t - 2.0f, 0.0f, 1.0f) * 0.8f)};
}

namespace {

using Draw = Canvas (*)(const Context&, const SourceTree&);

const std::vector<std::pair<const char*, Draw>>& figure_table() {
  static const std::vector<std::pair<const char*, Draw>> figures{
      {"blur", &blur_figure},
      {"pyramid_levels", &pyramid_figure},
      {"region_snapping", &region_figure},
      {"sample_table", [](const Context&, const SourceTree&) { return sample_table_figure(); }},
      {"traversal_nodes", &traversal_figure},
      {"reuse_groups", &reuse_figure},
      {"pipeline_stages", &pipeline_stages_figure},
      {"vsm_bleeding", &vsm_bleeding_figure},
      {"savsm_bleeding", &savsm_bleeding_figure},
      {"cascades_splits", [](const Context&, const SourceTree&) { return cascades_splits_figure(); }},
      {"backprojection", &backprojection_figure},
      {"backprojection_layers", &backprojection_layers_figure},
      {"techniques", &techniques_figure},
      {"area_edges", &area_edges_figure},
  };
  return figures;
}

}  // namespace

std::vector<std::string> figure_file_names() {
  std::vector<std::string> names;
  for (const auto& [name, draw] : figure_table()) names.push_back(std::string(name) + ".png");
  return names;
}

std::vector<fs::path> write_figures(const Context& context, const SourceTree& tree, const fs::path& out) {
  validate_output_directory(out);
  // One entry a picture: its file's name and what draws it.
  const auto& figures = figure_table();
  // Every picture is drawn before the first is written: a module that fails leaves the
  // directory as it was (not made, if it was missing), not five new pictures beside two old ones.
  std::vector<fs::path> paths;
  std::vector<Canvas> canvases;
  for (const auto& [name, draw] : figures) {
    paths.push_back(out / (std::string(name) + ".png"));
    canvases.push_back(draw(context, tree));
  }
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw Error("figures directory '" + out.string() + "': cannot be created");
  for (size_t i = 0; i < paths.size(); ++i) canvases[i].write_png(paths[i]);
  return paths;
}

}  // namespace pn
