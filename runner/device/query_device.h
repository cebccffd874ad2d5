// The executor seam of the query passes (architecture.md "Queries as textures"): a
// module's *_query.comp runs over a batch of queries on some device — an OpenGL 4.5 or ES 3.1
// context (gl/context.h), or a Vulkan device (vk/vulkan_device.h) — and nothing here names
// either. A query pass (passes/query_pass.h) compiles through this interface, uploads its
// textures through it and dispatches through it, so one check runs on every executor.
//
// Bindings are the numbers of glsl/passes/<pass>.h; a block is std140 bytes; the queries go up
// as RGBA32F images (query k at texel k, core/query_grid.h), the results come back as RGBA32F
// images or RGBA32UI words.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/image.h"
#include "core/query_grid.h"
#include "shader/loop_guard.h"
#include "shader/source_tree.h"
#include "shader/target.h"

namespace pn {

// A texture on one device, as a pass reads it (nearest filtering, clamped to the edge). Made by
// QueryDevice::upload, or by a device's own passes (a GL pyramid: gl/query_device_gl.h).
class DeviceTexture {
 public:
  virtual ~DeviceTexture() = default;
  DeviceTexture() = default;
  DeviceTexture(const DeviceTexture&) = delete;
  DeviceTexture& operator=(const DeviceTexture&) = delete;
};

// Where a pass reads its queries and writes its results (its header's binding numbers).
struct QueryBindings {
  std::vector<unsigned> inputs;        // a sampler per input image (a query's fields A, B, C, …)
  std::vector<unsigned> results;       // an RGBA32F image per result image
  std::vector<unsigned> word_results;  // an RGBA32UI image per result of exact words (sums modulo 2^64)
};

// A texture the pass reads besides its queries (a depth map, a pyramid, a table), at `binding`.
struct QueryTexture {
  unsigned binding;
  const DeviceTexture& texture;
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
  virtual ~QueryBatch() = default;
  QueryBatch() = default;
  QueryBatch(const QueryBatch&) = delete;
  QueryBatch& operator=(const QueryBatch&) = delete;
  virtual int width() const = 0;
  virtual int height() const = 0;
  virtual std::size_t inputs() const = 0;
  virtual std::size_t results() const = 0;
  virtual std::size_t word_results() const = 0;
  virtual QueryResults read() const = 0;
};

// One pass compiled for one device with one set of defines.
class QueryProgram {
 public:
  virtual ~QueryProgram() = default;
  QueryProgram() = default;
  QueryProgram(const QueryProgram&) = delete;
  QueryProgram& operator=(const QueryProgram&) = delete;
};

// Bounds on GPU work, set by `penumbra check` (docs/reliability.md): every compute loop
// guarded (shader/loop_guard.h) and every dispatch waited for with a deadline, so that a
// module copy that never terminates fails its check instead of hanging the machine.
struct DispatchBounds {
  bool enabled = false;
  unsigned loop_iterations = LoopGuardSettings{}.iterations;  // per loop and invocation
  double timeout_s = 60.0;              // per dispatch
};

class QueryDevice {
 public:
  virtual ~QueryDevice() = default;
  QueryDevice() = default;
  QueryDevice(const QueryDevice&) = delete;
  QueryDevice& operator=(const QueryDevice&) = delete;

  // "gl450", "es310", "vulkan", "hlsl": what the passes are compiled as (check's --api).
  virtual std::string query_api() const = 0;
  // `pass` (a path under the glsl root, e.g. "passes/pcf_query.comp") with `defines`. Throws
  // Error(ExitCode::failed) naming the pass on a compile error.
  virtual std::unique_ptr<QueryProgram> compile_query(const SourceTree& tree, const std::string& pass,
                                                      const std::vector<Define>& defines) const = 0;
  // `image` (1, 2 or 4 channels) as a texture the passes sample with texelFetch.
  virtual std::unique_ptr<DeviceTexture> upload(const Image& image) const = 0;
  // `inputs` all of one size (query_image of lists of one length); `results` RGBA32F and
  // `word_results` RGBA32UI images of that size. Throws Error on inputs of different sizes.
  virtual std::unique_ptr<QueryBatch> make_batch(const std::vector<Image>& inputs, std::size_t results,
                                                 std::size_t word_results) const = 0;
  // Binds the batch's inputs and results at `bindings`, `textures` and `block`, and runs
  // `program` over the batch's grid (whole work groups; the pass returns past the grid).
  // Throws Error unless the batch has an image per binding, or a texture was made elsewhere.
  virtual void dispatch(const QueryProgram& program, const QueryBindings& bindings, const QueryBatch& batch,
                        const std::vector<QueryTexture>& textures, const QueryBlock& block) const = 0;
};

// Error unless the batch has one image per binding (the check every executor's dispatch makes).
void check_batch_bindings(const QueryBindings& bindings, const QueryBatch& batch);
// The batch inputs' common size; Error unless there is one and all share it (every executor's batch).
std::pair<int, int> query_batch_size(const std::vector<Image>& inputs);

}  // namespace pn
