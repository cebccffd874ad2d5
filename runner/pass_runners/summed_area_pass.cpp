#include "pass_runners/summed_area_pass.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/format.h"
#include "core/query_grid.h"
#include "gl/std140.h"
#include "passes/summed_area_query.h"

namespace pn::glsl {
#include "passes/summed_area_build.h"
PN_STD140_SIZE(PnSummedAreaBuildParams, 16);
PN_STD140_OFFSET(PnSummedAreaBuildParams, direction, 0);
PN_STD140_OFFSET(PnSummedAreaBuildParams, unitRange, 8);
}  // namespace pn::glsl

namespace pn {
namespace {

std::vector<Define> fraction_define(int fraction_bits) {
  if (fraction_bits < 0 || fraction_bits > kSummedAreaMagnitudeBits)
    throw Error("summed-area fraction bits " + std::to_string(fraction_bits) + ": expected 0 to " +
                std::to_string(kSummedAreaMagnitudeBits));
  if (fraction_bits == kSummedAreaFractionBits) return {};
  return {{"PN_SUMMED_AREA_FRACTION_BITS", std::to_string(fraction_bits)}};
}

// The query passes' rectangles and float results, and their exact sums (`words`) where they have them.
QueryBindings query_bindings(bool words) {
  QueryBindings b{{PN_SUMMED_AREA_QUERY_RECTS_BINDING}, {PN_SUMMED_AREA_QUERY_FLOAT_IMAGE}, {}};
  if (words) b.word_results.push_back(PN_SUMMED_AREA_QUERY_FIXED_IMAGE);
  return b;
}

// The two build dispatches (summed_area_build.comp): one invocation per row of the table into
// the row-prefix table, then one per column into the table (both of the table's shape).
void build_lines(const QueryDevice& device, const QueryProgram& program, const DeviceTexture& depth_map,
                 const DeviceTexture& row_prefix, const DeviceTexture& table, glsl::vec2 unit_range) {
  const glsl::PnSummedAreaBuildParams rows{PN_SUMMED_AREA_ROWS, 0, unit_range};
  // The pass declares both inputs and reads one a dispatch; both are bound (Vulkan binds every
  // resource a pipeline declares).
  const std::vector<QueryTexture> inputs{{PN_SUMMED_AREA_BUILD_MAP_BINDING, depth_map},
                                         {PN_SUMMED_AREA_BUILD_ROWS_BINDING, row_prefix}};
  device.run(program, {inputs, {{PN_SUMMED_AREA_BUILD_TARGET_IMAGE, row_prefix}}, {}, query_block(rows)},
             table.shape().height, 1);
  const glsl::PnSummedAreaBuildParams columns{PN_SUMMED_AREA_COLUMNS, 0, unit_range};
  device.run(program, {inputs, {{PN_SUMMED_AREA_BUILD_TARGET_IMAGE, table}}, {}, query_block(columns)},
             table.shape().width, 1);
}

// The rectangles as a query image (origin x, y, width, height), each coordinate within ±2^24
// (they travel as floats); throws Error otherwise.
Image rect_query_image(const std::vector<Rect>& rects) {
  std::vector<Query> q;
  for (const Rect& r : rects) {
    for (int v : {r.x, r.y, r.width, r.height})
      if (std::abs(v) > (1 << 24))
        throw Error("summed-area query rectangle coordinate " + std::to_string(v) + ": expected within ±2^24");
    q.push_back({float(r.x), float(r.y), float(r.width), float(r.height)});
  }
  return query_image(q);
}

// Refuses a depth map of other than 1 to kSummedAreaMaxSide texels a side.
void check_map_size(int width, int height) {
  if (width < 1 || height < 1 || width > kSummedAreaMaxSide || height > kSummedAreaMaxSide)
    throw Error("summed-area table of a " + std::to_string(width) + "x" + std::to_string(height) +
                " map: expected 1 to " + std::to_string(kSummedAreaMaxSide) + " texels a side");
}

}  // namespace

std::size_t SummedAreaPass::memory_bytes(int width, int height) {
  return 16 * static_cast<std::size_t>(width + 1) * static_cast<std::size_t>(height + 1);
}

SummedAreaPass::SummedAreaPass(const QueryDevice& device, const SourceTree& tree, int fraction_bits)
    : device_(&device),
      fraction_bits_(fraction_bits),
      build_(device.compile_query(tree, "passes/summed_area_build.comp", fraction_define(fraction_bits))),
      query_(device, tree, "passes/summed_area_query.comp", query_bindings(true), fraction_define(fraction_bits)) {}

SummedAreaTable SummedAreaPass::build(const DeviceTexture& depth_map, int width, int height) const {
  check_map_size(width, height);
  const TextureShape shape{TexelFormat::rgba32ui, width + 1, height + 1};
  const std::unique_ptr<DeviceTexture> row_prefix = device_->make_texture(shape);
  SummedAreaTable table{device_->make_texture(shape), width, height};
  build_lines(*device_, *build_, depth_map, *row_prefix, *table.texture, {0.0f, 1.0f});
  return table;
}

std::vector<SummedAreaQueryResult> SummedAreaPass::query(const SummedAreaTable& table,
                                                         const std::vector<Rect>& rects) const {
  if (rects.empty()) return {};
  const QueryResults r =
      query_.run(std::vector<Image>{rect_query_image(rects)}, {{PN_SUMMED_AREA_QUERY_TABLE_BINDING, *table.texture}});
  std::vector<SummedAreaQueryResult> out;
  for (size_t k = 0; k < rects.size(); ++k) {
    const Query q = r.at(0, k);
    const std::uint32_t* t = &r.words[0][k * 4];
    SummedAreaQueryResult r;
    r.fixed_sum = (static_cast<std::uint64_t>(t[1]) << 32) | t[0];
    r.count = t[2];
    r.texels = t[3];
    r.sum = q[0];
    r.mean = q[1];
    out.push_back(r);
  }
  return out;
}

const char* moments_table_kind_name(MomentsTableKind kind) {
  return kind == MomentsTableKind::fixed ? "fixed" : "float";
}

UnitRange unit_range(double near_depth, double far_depth) {
  if (!std::isfinite(near_depth) || !std::isfinite(far_depth) || near_depth < 0 || !(far_depth > near_depth))
    throw Error("moments table depth range [" + format_number("%g", near_depth) + ", " +
                format_number("%g", far_depth) + "]: expected finite 0 <= near < far");
  const float scale = static_cast<float>(1.0 / (far_depth - near_depth));
  if (!std::isfinite(scale) || !(scale > 0.0f))
    throw Error("moments table depth range [" + format_number("%g", near_depth) + ", " +
                format_number("%g", far_depth) + "]: its scale 1 / (far - near) is not a finite float > 0");
  return {static_cast<float>(near_depth), scale};
}

SummedAreaMomentsPass::SummedAreaMomentsPass(const QueryDevice& device, const SourceTree& tree, int moment_bits)
    : device_(&device),
      tree_(&tree),
      moment_bits_(moment_bits),
      fixed_query_(device, tree, "passes/summed_area_moments_query.comp", query_bindings(true),
                   defines(MomentsTableKind::fixed, "PN_SUMMED_AREA_QUERY_KIND"), QueryCompile::on_first_use),
      float_query_(device, tree, "passes/summed_area_moments_query.comp", query_bindings(false),
                   defines(MomentsTableKind::floating, "PN_SUMMED_AREA_QUERY_KIND"), QueryCompile::on_first_use) {
  if (moment_bits < 0 || moment_bits > kSummedAreaMaxMomentBits)
    throw Error("summed-area moment bits " + std::to_string(moment_bits) + ": expected 0 to " +
                std::to_string(kSummedAreaMaxMomentBits));
}

std::vector<Define> SummedAreaMomentsPass::defines(MomentsTableKind kind, const char* kind_macro) const {
  std::vector<Define> d{{kind_macro, std::to_string(static_cast<int>(kind))}};
  if (moment_bits_ != kSummedAreaMomentBits) d.push_back({"PN_SUMMED_AREA_MOMENT_BITS", std::to_string(moment_bits_)});
  return d;
}

std::size_t SummedAreaMomentsPass::memory_bytes(const QueryDevice& device, int width, int height,
                                                MomentsTableKind kind) {
  const std::size_t texel = kind == MomentsTableKind::fixed ? 16 : 4 * static_cast<std::size_t>(device.storage_channels(2));
  return texel * static_cast<std::size_t>(width + 1) * static_cast<std::size_t>(height + 1);
}

MomentsTable SummedAreaMomentsPass::build(const DeviceTexture& depth_map, int width, int height, MomentsTableKind kind,
                                          UnitRange range) const {
  check_map_size(width, height);
  const bool fixed = kind == MomentsTableKind::fixed;
  const TextureShape shape = fixed ? TextureShape{TexelFormat::rgba32ui, width + 1, height + 1}
                                   : float_shape(width + 1, height + 1, device_->storage_channels(2));
  std::unique_ptr<QueryProgram>& program = build_[fixed ? 0 : 1];
  if (!program)
    program = device_->compile_query(*tree_, "passes/summed_area_build.comp", defines(kind, "PN_SUMMED_AREA_BUILD_KIND"));
  const std::unique_ptr<DeviceTexture> row_prefix = device_->make_texture(shape);
  MomentsTable table{device_->make_texture(shape), width, height, kind, range};
  build_lines(*device_, *program, depth_map, *row_prefix, *table.texture, {range.offset, range.scale});
  return table;
}

std::vector<MomentsQueryResult> SummedAreaMomentsPass::query(const MomentsTable& table,
                                                             const std::vector<Rect>& rects) const {
  if (rects.empty()) return {};
  const bool fixed = table.kind == MomentsTableKind::fixed;
  const QueryResults m = (fixed ? fixed_query_ : float_query_)
                             .run(std::vector<Image>{rect_query_image(rects)},
                                  {{PN_SUMMED_AREA_QUERY_TABLE_BINDING, *table.texture}});
  std::vector<MomentsQueryResult> out;
  for (size_t k = 0; k < rects.size(); ++k) {
    const Query r = m.at(0, k);
    MomentsQueryResult result;
    if (fixed) {
      const std::uint32_t* t = &m.words[0][k * 4];
      result.sum_q = (static_cast<std::uint64_t>(t[1]) << 32) | t[0];
      result.sum_q2 = (static_cast<std::uint64_t>(t[3]) << 32) | t[2];
    }
    result.mean = r[0];
    result.variance = r[1];
    result.texels = static_cast<std::uint32_t>(r[2]);
    out.push_back(result);
  }
  return out;
}

}  // namespace pn
