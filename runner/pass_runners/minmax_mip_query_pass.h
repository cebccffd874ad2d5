// Runner side of glsl/passes/minmax_mip_query.comp: minmax_mip.glsl's reads of a built chain —
// pnMipSquareMinMax over squares, pnMipCombineTexel at texels — over a batch.
#pragma once

#include <array>
#include <vector>

#include "pass_runners/minmax_mip_pass.h"
#include "pass_runners/query_pass.h"
#include "shader/source_tree.h"

namespace pn {

struct MinMaxMipQuery {
  int origin_x = 0, origin_y = 0, side = 0;  // pnMipSquareMinMax's square (the chain's map size)
  int level = 0, texel_x = 0, texel_y = 0;   // pnMipCombineTexel's
};

struct MinMaxMipQueryResult {
  float min = 0.0f, max = 0.0f;       // pnMipSquareMinMax
  std::array<float, 4> combined{};    // pnMipCombineTexel: (min, max) of two nodes
};

class MinMaxMipQueryPass {
 public:
  MinMaxMipQueryPass(const QueryDevice& device, const SourceTree& tree);
  std::vector<MinMaxMipQueryResult> run(const MinMaxMipChain& chain, const std::vector<MinMaxMipQuery>& queries) const;

 private:
  QueryPass query_;
};

}  // namespace pn
