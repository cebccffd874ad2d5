// The one shape of every query pass (a module's *_query.comp checked over a
// batch of inputs, architecture.md "Queries as textures"): the queries
// uploaded as RGBA float images (query k at texel k, core/query_grid.h), one
// result image per output, the pass's uniform block and the textures it reads
// bound, one dispatch over the grid, the results read back.
//
// This is the seam a second backend implements again, so nothing in the
// interface names GL: bindings are the numbers of glsl/passes/<pass>.h, a
// block is bytes, a texture is the runner's GlObject handle.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/query_grid.h"
#include "gl/pass_variants.h"
#include "gl/texture.h"

namespace pn {

// Where a pass reads its queries and writes its results (its header's binding numbers).
struct QueryBindings {
  std::vector<unsigned> inputs;        // a sampler per input image (a query's fields A, B, C, …)
  std::vector<unsigned> results;       // an RGBA32F image per result image
  std::vector<unsigned> word_results;  // an RGBA32UI image per result of exact words (sums modulo 2^64)
};

// A texture the pass reads besides its queries (a depth map, a pyramid, a table), at `binding`.
struct QueryTexture {
  unsigned binding;
  const GlObject& texture;
};

// A pass's uniform block (a shared block of glsl/passes/<pass>.h: std140 layout, Block::binding);
// empty for a pass without one. It points at the block, which must outlive the dispatch.
struct QueryBlock {
  unsigned binding = 0;
  const void* data = nullptr;
  std::size_t size = 0;
};
template <class Block>
QueryBlock query_block(const Block& block) {
  return {Block::binding, &block, sizeof block};
}

// What one dispatch wrote, read back: result k of query k at texel k of each image (query_result).
struct QueryResults {
  std::vector<Image> images;                      // per QueryBindings::results
  std::vector<std::vector<std::uint32_t>> words;  // per QueryBindings::word_results: 4 words a texel

  Query at(std::size_t image, std::size_t k) const { return query_result(images[image], k); }
  // Image `image`'s results of the first `count` queries.
  std::vector<Query> list(std::size_t image, std::size_t count) const;
};

// The queries of one run on the device and the images their results go to: made for one run, or
// dispatched many times (a benchmark times the dispatches alone).
class QueryBatch {
 public:
  // `inputs` all of one size (query_image of lists of one length); `results` RGBA32F and
  // `word_results` RGBA32UI images of that size.
  QueryBatch(const Context& context, const std::vector<Image>& inputs, std::size_t results,
             std::size_t word_results = 0);
  int width() const { return width_; }
  int height() const { return height_; }
  QueryResults read() const;

 private:
  friend class QueryPass;
  const Context* context_;
  int width_ = 0, height_ = 0;
  std::vector<FloatTexture> inputs_, results_;
  std::vector<GlObject> word_results_;
};

// When a pass's program is compiled: with the pass (a check's or a benchmark's timing never sees
// it), or on its first run (a pass one of whose variants a frame may never use).
enum class QueryCompile { now, on_first_use };

class QueryPass {
 public:
  // `pass`: a path under the glsl root (e.g. "passes/region_query.comp"), compiled with `defines`.
  // Throws Error as compile_pass.
  QueryPass(const Context& context, const SourceTree& tree, const std::string& pass, QueryBindings bindings,
            std::vector<Define> defines = {}, QueryCompile compile = QueryCompile::now);

  // Binds the batch's inputs and results at the pass's bindings, `textures` and `block`, and
  // dispatches over the batch's grid. Throws Error unless the batch has an image per binding.
  void dispatch(const QueryBatch& batch, const std::vector<QueryTexture>& textures = {},
                const QueryBlock& block = {}) const;
  // A batch of `inputs` dispatched once and read back.
  QueryResults run(const std::vector<Image>& inputs, const std::vector<QueryTexture>& textures = {},
                   const QueryBlock& block = {}) const;
  // The same for lists of queries (query_image of each).
  QueryResults run(const std::vector<std::vector<Query>>& inputs, const std::vector<QueryTexture>& textures = {},
                   const QueryBlock& block = {}) const;

 private:
  const Context* context_;
  QueryBindings bindings_;
  std::vector<Define> defines_;
  PassVariants programs_;  // the one variant of defines_, compiled as QueryCompile says
};

}  // namespace pn
