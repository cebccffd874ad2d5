// Runner side of glsl/passes/summed_area_build.comp and summed_area_query.comp:
// builds glsl/summed_area.glsl's table from a depth texture (two dispatches:
// rows, then columns) and sums a batch of rectangles from it.
#pragma once

#include <cstdint>
#include <vector>

#include "gl/compute_program.h"
#include "reference/summed_area_reference.h"
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
                                           const std::vector<SummedAreaRect>& rects) const;

  int fraction_bits() const { return fraction_bits_; }

  // GPU memory of a width × height map's table (RGBA32UI, (width + 1) × (height + 1)); the
  // build's row-prefix table, as large, lives only while building.
  static std::size_t memory_bytes(int width, int height);

 private:
  const Context* context_;
  int fraction_bits_;
  ComputeProgram build_;
  ComputeProgram query_;
};

}  // namespace pn
