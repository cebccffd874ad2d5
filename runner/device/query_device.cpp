#include "device/query_device.h"

#include "core/error.h"

namespace pn {

std::vector<Query> QueryResults::list(std::size_t image, std::size_t count) const {
  std::vector<Query> out;
  for (std::size_t k = 0; k < count; ++k) out.push_back(at(image, k));
  return out;
}

void check_batch_bindings(const QueryBindings& bindings, const QueryBatch& batch) {
  if (batch.inputs() != bindings.inputs.size() || batch.results() != bindings.results.size() ||
      batch.word_results() != bindings.word_results.size())
    throw Error("query pass: a batch of " + std::to_string(batch.inputs()) + " inputs and " +
                std::to_string(batch.results() + batch.word_results()) +
                " results: expected one per binding of the pass");
}

std::pair<int, int> query_batch_size(const std::vector<Image>& inputs) {
  if (inputs.empty()) throw Error("query batch: expected at least one input image");
  const int width = inputs.front().width, height = inputs.front().height;
  for (const Image& input : inputs)
    if (input.width != width || input.height != height)
      throw Error("query batch: input images of " + std::to_string(input.width) + "x" + std::to_string(input.height) +
                  " and " + std::to_string(width) + "x" + std::to_string(height) + ": expected one size");
  return {width, height};
}

}  // namespace pn
