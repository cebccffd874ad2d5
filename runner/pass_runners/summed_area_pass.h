// Runner side of glsl/passes/summed_area_build.comp and summed_area_query.comp:
// builds glsl/summed_area.glsl's table from a depth texture (two dispatches:
// rows, then columns) and sums a batch of rectangles from it.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/texel_rect.h"
#include "device/query_device.h"
#include "modules/summed_area_face.h"
#include "pass_runners/query_pass.h"
#include "shader/source_tree.h"

namespace pn {

// A built table: (width + 1) × (height + 1) texels of RGBA32UI (sum low word,
// high word, finite count, 0) for a width × height map.
struct SummedAreaTable {
  std::unique_ptr<DeviceTexture> texture;
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
  SummedAreaPass(const QueryDevice& device, const SourceTree& tree, int fraction_bits = kSummedAreaFractionBits);

  // `depth_map`: a single-channel float texture of `width` × `height` (N × M), 1 <= N, M <=
  // kSummedAreaMaxSide (and N + 1, M + 1 within the device's texture size); throws Error otherwise.
  SummedAreaTable build(const DeviceTexture& depth_map, int width, int height) const;

  // One result per rectangle (origins and sizes within ±2^24, as they travel as floats).
  std::vector<SummedAreaQueryResult> query(const SummedAreaTable& table,
                                           const std::vector<Rect>& rects) const;

  int fraction_bits() const { return fraction_bits_; }

  // GPU memory of a width × height map's table (RGBA32UI, (width + 1) × (height + 1)); the
  // build's row-prefix table, as large, lives only while building.
  static std::size_t memory_bytes(int width, int height);

 private:
  const QueryDevice* device_;
  int fraction_bits_;
  std::unique_ptr<QueryProgram> build_;
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
  std::unique_ptr<DeviceTexture> texture;
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
  SummedAreaMomentsPass(const QueryDevice& device, const SourceTree& tree, int moment_bits = kSummedAreaMomentBits);

  // The moments table of a single-channel float depth texture of `width` × `height` (N × M), 1 <=
  // N, M <= kSummedAreaMaxSide; throws Error otherwise.
  MomentsTable build(const DeviceTexture& depth_map, int width, int height, MomentsTableKind kind,
                     UnitRange range) const;
  std::vector<MomentsQueryResult> query(const MomentsTable& table, const std::vector<Rect>& rects) const;

  int moment_bits() const { return moment_bits_; }
  // GPU memory of a width × height map's table (the row-prefix table, as large, lives only while building).
  static std::size_t memory_bytes(const QueryDevice& device, int width, int height, MomentsTableKind kind);

 private:
  std::vector<Define> defines(MomentsTableKind kind, const char* kind_macro) const;
  const QueryDevice* device_;
  const SourceTree* tree_;
  int moment_bits_;
  mutable std::unique_ptr<QueryProgram> build_[2];  // by kind (fixed, floating), each compiled on first use
  QueryPass fixed_query_, float_query_;  // by PN_SUMMED_AREA_QUERY_KIND, each compiled on first use
};

}  // namespace pn
