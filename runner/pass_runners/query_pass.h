// The one shape of every query pass (a module's *_query.comp checked over a
// batch of inputs, architecture.md "Queries as textures"): the queries
// uploaded as RGBA float images (query k at texel k, core/query_grid.h), one
// result image per output, the pass's uniform block and the textures it reads
// bound, one dispatch over the grid, the results read back.
//
// It runs on any executor of device/query_device.h — a GL context, or a Vulkan device —
// so a check written on QueryPass runs on every API `penumbra check --api` names.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "device/query_device.h"
#include "shader/source_tree.h"
#include "shader/target.h"

namespace pn {

// When a pass's program is compiled: with the pass (a check's or a benchmark's timing never sees
// it), or on its first run (a pass one of whose variants a frame may never use).
enum class QueryCompile { now, on_first_use };

class QueryPass {
 public:
  // `pass`: a path under the glsl root (e.g. "passes/region_query.comp"), compiled with `defines`.
  // Throws Error as QueryDevice::compile_query.
  QueryPass(const QueryDevice& device, const SourceTree& tree, const std::string& pass, QueryBindings bindings,
            std::vector<Define> defines = {}, QueryCompile compile = QueryCompile::now);

  const QueryDevice& device() const { return *device_; }
  // A batch for this pass's bindings, to dispatch many times.
  std::unique_ptr<QueryBatch> batch(const std::vector<Image>& inputs) const;
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
  const QueryProgram& program() const;
  const QueryDevice* device_;
  SourceTree tree_;
  std::string pass_;
  QueryBindings bindings_;
  std::vector<Define> defines_;
  mutable std::unique_ptr<QueryProgram> program_;  // compiled as QueryCompile says
};

}  // namespace pn
