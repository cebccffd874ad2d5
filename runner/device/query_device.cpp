#include "device/query_device.h"

#include <limits>

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

std::vector<QueryBlock> uniform_blocks(const PassResources& resources) {
  std::vector<QueryBlock> out;
  if (resources.block.data != nullptr) out.push_back(resources.block);
  out.insert(out.end(), resources.more_blocks.begin(), resources.more_blocks.end());
  return out;
}

namespace {

// The stages of a device without timestamp queries: named, their times NaN.
class UntimedStages final : public StageTimes {
 public:
  void start() override {}
  void stage(const std::string& name) override { names_.push_back(name); }
  std::vector<std::pair<std::string, double>> read() const override {
    std::vector<std::pair<std::string, double>> out;
    for (const std::string& name : names_) out.emplace_back(name, std::numeric_limits<double>::quiet_NaN());
    return out;
  }

 private:
  std::vector<std::string> names_;
};

}  // namespace

std::unique_ptr<StageTimes> QueryDevice::stage_clock() const { return std::make_unique<UntimedStages>(); }

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

namespace pn {

int texel_channels(TexelFormat format) {
  switch (format) {
    case TexelFormat::r32f: return 1;
    case TexelFormat::rg32f: return 2;
    case TexelFormat::rgba32f:
    case TexelFormat::rgba32ui: return 4;
  }
  return 4;
}

TextureShape float_shape(int width, int height, int channels, int levels) {
  const TexelFormat format = channels == 1 ? TexelFormat::r32f : channels == 2 ? TexelFormat::rg32f : TexelFormat::rgba32f;
  return {format, width, height, levels, 1, false};
}

}  // namespace pn
