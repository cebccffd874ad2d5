#include "passes/summed_area_pass.h"

#include "gl/query_device_gl.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/format.h"
#include "core/query_grid.h"
#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"
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

// An RGBA32UI texture, nearest filtering (read with texelFetch only).
GlObject make_uint4_texture(const Context& context, int width, int height) {
  GLint max_size = 0;
  context.gl().GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (width > max_size || height > max_size)
    throw Error("summed-area table " + std::to_string(width) + "x" + std::to_string(height) +
                ": expected at most GL_MAX_TEXTURE_SIZE (" + std::to_string(max_size) + ") on each side");
  GlObject texture = make_texture(context, GL_TEXTURE_2D, GL_RGBA32UI, width, height);
  context.throw_if_gl_error("allocating a summed-area table");
  return texture;
}

// The query passes' rectangles and float results, and their exact sums (`words`) where they have them.
QueryBindings query_bindings(bool words) {
  QueryBindings b{{PN_SUMMED_AREA_QUERY_RECTS_BINDING}, {PN_SUMMED_AREA_QUERY_FLOAT_IMAGE}, {}};
  if (words) b.word_results.push_back(PN_SUMMED_AREA_QUERY_FIXED_IMAGE);
  return b;
}

void texture_size(const Context& context, const GlObject& texture, int& width, int& height) {
  GLint w = 0, h = 0, previous = 0;
  const auto& gl = context.gl();
  gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &previous);  // bind-to-query, then put back what was there
  gl.BindTexture(GL_TEXTURE_2D, texture.id());
  gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
  gl.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
  context.throw_if_gl_error("reading a depth map's size");
  width = w, height = h;
}

// The two build dispatches (summed_area_build.comp): one invocation per row of the table into
// the row-prefix table, then one per column into the table.
// The table is tw × th texels.
void build_lines(const Context& context, const ComputeProgram& program, const GlObject& depth_map,
                 const GlObject& row_prefix, const GlObject& table, int tw, int th, GLenum format,
                 glsl::vec2 unit_range) {
  {
    PassBindings bind(context);
    bind.uniform(glsl::PnSummedAreaBuildParams{PN_SUMMED_AREA_ROWS, 0, unit_range});
    bind.texture(PN_SUMMED_AREA_BUILD_MAP_BINDING, depth_map);
    bind.image(PN_SUMMED_AREA_BUILD_TARGET_IMAGE, row_prefix, GL_WRITE_ONLY, format);
    program.dispatch(th, 1);
  }
  PassBindings bind(context);
  bind.uniform(glsl::PnSummedAreaBuildParams{PN_SUMMED_AREA_COLUMNS, 0, unit_range});
  bind.texture(PN_SUMMED_AREA_BUILD_ROWS_BINDING, row_prefix);
  bind.image(PN_SUMMED_AREA_BUILD_TARGET_IMAGE, table, GL_WRITE_ONLY, format);
  program.dispatch(tw, 1);
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

// The depth map's size, refused unless 1 to kSummedAreaMaxSide texels a side.
void table_map_size(const Context& context, const GlObject& depth_map, int& width, int& height) {
  texture_size(context, depth_map, width, height);
  if (width < 1 || height < 1 || width > kSummedAreaMaxSide || height > kSummedAreaMaxSide)
    throw Error("summed-area table of a " + std::to_string(width) + "x" + std::to_string(height) +
                " map: expected 1 to " + std::to_string(kSummedAreaMaxSide) + " texels a side");
}

}  // namespace

std::size_t SummedAreaPass::memory_bytes(int width, int height) {
  return 16 * static_cast<std::size_t>(width + 1) * static_cast<std::size_t>(height + 1);
}

SummedAreaPass::SummedAreaPass(const Context& context, const SourceTree& tree, int fraction_bits)
    : context_(&context),
      fraction_bits_(fraction_bits),
      build_(compile_pass(context, tree, "passes/summed_area_build.comp", fraction_define(fraction_bits))),
      query_(context, tree, "passes/summed_area_query.comp", query_bindings(true), fraction_define(fraction_bits)) {}

SummedAreaTable SummedAreaPass::build(const GlObject& depth_map) const {
  SummedAreaTable table;
  table_map_size(*context_, depth_map, table.width, table.height);
  const int tw = table.width + 1, th = table.height + 1;
  const GlObject row_prefix = make_uint4_texture(*context_, tw, th);
  table.texture = make_uint4_texture(*context_, tw, th);
  build_lines(*context_, build_, depth_map, row_prefix, table.texture, tw, th, GL_RGBA32UI, {0.0f, 1.0f});
  return table;
}

std::vector<SummedAreaQueryResult> SummedAreaPass::query(const SummedAreaTable& table,
                                                         const std::vector<Rect>& rects) const {
  if (rects.empty()) return {};
  const QueryResults r =
      query_.run(std::vector<Image>{rect_query_image(rects)}, {{PN_SUMMED_AREA_QUERY_TABLE_BINDING, GlDeviceTexture(table.texture)}});
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

SummedAreaMomentsPass::SummedAreaMomentsPass(const Context& context, const SourceTree& tree, int moment_bits)
    : context_(&context),
      moment_bits_(moment_bits),
      build_(context, tree, "passes/summed_area_build.comp"),
      fixed_query_(context, tree, "passes/summed_area_moments_query.comp", query_bindings(true),
                   defines(MomentsTableKind::fixed, "PN_SUMMED_AREA_QUERY_KIND"), QueryCompile::on_first_use),
      float_query_(context, tree, "passes/summed_area_moments_query.comp", query_bindings(false),
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

std::size_t SummedAreaMomentsPass::memory_bytes(const Context& context, int width, int height, MomentsTableKind kind) {
  const std::size_t texel = kind == MomentsTableKind::fixed ? 16 : 4 * static_cast<std::size_t>(image_channels(context, 2));
  return texel * static_cast<std::size_t>(width + 1) * static_cast<std::size_t>(height + 1);
}

MomentsTable SummedAreaMomentsPass::build(const GlObject& depth_map, MomentsTableKind kind, UnitRange range) const {
  MomentsTable table;
  table_map_size(*context_, depth_map, table.width, table.height);
  table.kind = kind;
  table.range = range;
  const int tw = table.width + 1, th = table.height + 1;
  const bool fixed = kind == MomentsTableKind::fixed;
  const int channels = image_channels(*context_, 2);
  const auto make = [&]() -> GlObject {
    if (fixed) return make_uint4_texture(*context_, tw, th);
    GLint max_size = 0;
    context_->gl().GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    if (tw > max_size || th > max_size)
      throw Error("summed-area table " + std::to_string(tw) + "x" + std::to_string(th) +
                  ": expected at most GL_MAX_TEXTURE_SIZE (" + std::to_string(max_size) + ") on each side");
    return make_float_texture(*context_, tw, th, channels);
  };
  const GLenum format = fixed ? GL_RGBA32UI : float_format(channels);
  const ComputeProgram& program = build_.get(defines(kind, "PN_SUMMED_AREA_BUILD_KIND"));
  const GlObject row_prefix = make();
  table.texture = make();
  build_lines(*context_, program, depth_map, row_prefix, table.texture, tw, th, format, {range.offset, range.scale});
  return table;
}

std::vector<MomentsQueryResult> SummedAreaMomentsPass::query(const MomentsTable& table,
                                                             const std::vector<Rect>& rects) const {
  if (rects.empty()) return {};
  const bool fixed = table.kind == MomentsTableKind::fixed;
  const QueryResults m = (fixed ? fixed_query_ : float_query_)
                             .run(std::vector<Image>{rect_query_image(rects)},
                                  {{PN_SUMMED_AREA_QUERY_TABLE_BINDING, GlDeviceTexture(table.texture)}});
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
