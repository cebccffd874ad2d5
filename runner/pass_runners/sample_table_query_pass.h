// Runner side of glsl/passes/sample_table_query.comp (sample_table.glsl's
// selection and scaling over a batch of pixels, sides and sample indices) and
// of glsl/passes/correlated_multi_jitter_query.comp (its stateless option's
// sample positions).
#pragma once

#include "core/image.h"
#include "pass_runners/query_pass.h"
#include "sampling/sample_table_generator.h"

namespace pn {

class SampleTableQueryPass {
 public:
  SampleTableQueryPass(const QueryDevice& device, const SourceTree& tree);
  // `queries`: RGBA (pixel x, y, region side, i) per texel; returns two images of the same size:
  // (k, first column, last column, set) and (column, texel x, texel y, 0).
  std::vector<Image> run(const SampleTable& table, const Image& queries) const;

 private:
  QueryPass query_;
};

class CorrelatedMultiJitterQueryPass {
 public:
  CorrelatedMultiJitterQueryPass(const QueryDevice& device, const SourceTree& tree);
  // `queries`: RGBA (group k, sample index, set, seed) per texel; returns (x, y, 0, 0) of the same size.
  Image run(const Image& queries) const;

 private:
  QueryPass query_;
};

}  // namespace pn
