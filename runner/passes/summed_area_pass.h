// Runner side of glsl/passes/summed_area_build.comp and summed_area_query.comp:
// builds glsl/summed_area.glsl's table from a depth texture (two dispatches:
// rows, then columns) and sums a batch of rectangles from it.
#pragma once

#include <cstdint>
#include <vector>

#include "gl/compute_program.h"
#include "gl/pass_variants.h"
#include "core/texel_rect.h"
#include "modules/summed_area.h"
#include "passes/query_pass.h"
#include "shader/source_tree.h"

namespace pn {

// A built table: (width + 1) × (height + 1) texels of RGBA32UI (sum low word,
// high word, finite count, 0) for a width × height map.
struct SummedAreaTable {
  GlObject texture;
  int width = 0, height = 0;  // the map's size
};

struct SummedAreaQueryResult {
  std::uint64_t fixed_sum = 0;  // Σ q mod 2^64, two's complement (fixedSum's words)
  std::uint32_t count = 0;      // finite texels
  std::uint32_t texels = 0;     // texels covered
  float sum = 0.0f;             // fixedSum as a float: the depth sum
  float mean = 0.0f;            // pnSummedAreaMean
};

class SummedAreaPass {
 public:
  // Compiles both passes with PN_SUMMED_AREA_FRACTION_BITS `fraction_bits` (the module's default
  // unless given). Throws Error for fraction bits outside 0..52.
  SummedAreaPass(const Context& context, const SourceTree& tree, int fraction_bits = kSummedAreaFractionBits);

  // `depth_map`: a single-channel float texture of any size N × M, 1 <= N, M <= kSummedAreaMaxSide
  // (and N + 1, M + 1 within GL_MAX_TEXTURE_SIZE); throws Error otherwise.
  SummedAreaTable build(const GlObject& depth_map) const;

  // One result per rectangle (origins and sizes within ±2^24, as they travel as floats).
  std::vector<SummedAreaQueryResult> query(const SummedAreaTable& table,
                                           const std::vector<Rect>& rects) const;

  int fraction_bits() const { return fraction_bits_; }

  // GPU memory of a width × height map's table (RGBA32UI, (width + 1) × (height + 1)); the
  // build's row-prefix table, as large, lives only while building.
  static std::size_t memory_bytes(int width, int height);

 private:
  const Context* context_;
  int fraction_bits_;
  ComputeProgram build_;
  QueryPass query_;
};

// ---- Moments tables (seed 004's summed-area variance shadow maps) ----------

enum class MomentsTableKind {
  fixed = PN_SUMMED_AREA_KIND_MOMENTS,             // RGBA32UI (Σq, Σq²) modulo 2^64: exact box sums
  floating = PN_SUMMED_AREA_KIND_FLOAT_MOMENTS,    // RG32F (RGBA32F on ES) (Σ(x − ½), Σ(x − ½)²)
};
const char* moments_table_kind_name(MomentsTableKind kind);  // "fixed", "float"

// The table's unit depth x = clamp((d − offset) · scale, 0, 1) (pnSummedAreaUnitDepth).
struct UnitRange {
  float offset = 0.0f;  // the light's near plane
  float scale = 1.0f;   // 1 / (far − near), rounded to float once
};
// Throws Error unless 0 <= near < far, both finite, and the scale is a finite float > 0.
UnitRange unit_range(double near_depth, double far_depth);

struct MomentsTable {
  GlObject texture;
  int width = 0, height = 0;  // the map's size; the table is one larger each way
  MomentsTableKind kind = MomentsTableKind::fixed;
  UnitRange range;
};

struct MomentsQueryResult {
  std::uint64_t sum_q = 0, sum_q2 = 0;  // fixed tables only: Σq and Σq² modulo 2^64
  float mean = 0.0f, variance = 0.0f;   // of x, from pnSummedAreaRectMoments / …FloatMoments
  std::uint32_t texels = 0;             // texels covered
};

class SummedAreaMomentsPass {
 public:
  // Compiles the build pass per kind and the moments query pass per kind (on first use), with
  // PN_SUMMED_AREA_MOMENT_BITS `moment_bits` (the module's default unless given; throws Error
  // outside 0..PN_SUMMED_AREA_MAX_MOMENT_BITS).
  SummedAreaMomentsPass(const Context& context, const SourceTree& tree, int moment_bits = kSummedAreaMomentBits);

  // The moments table of a single-channel float depth texture, N × M with 1 <= N, M <=
  // kSummedAreaMaxSide; throws Error otherwise.
  MomentsTable build(const GlObject& depth_map, MomentsTableKind kind, UnitRange range) const;
  std::vector<MomentsQueryResult> query(const MomentsTable& table, const std::vector<Rect>& rects) const;

  int moment_bits() const { return moment_bits_; }
  // GPU memory of a width × height map's table (the row-prefix table, as large, lives only while building).
  static std::size_t memory_bytes(const Context& context, int width, int height, MomentsTableKind kind);

 private:
  std::vector<Define> defines(MomentsTableKind kind, const char* kind_macro) const;
  const Context* context_;
  int moment_bits_;
  PassVariants build_;
  QueryPass fixed_query_, float_query_;  // by PN_SUMMED_AREA_QUERY_KIND, each compiled on first use
};

}  // namespace pn
