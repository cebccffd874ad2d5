#include "passes/query_pass.h"

#include <string>

#include "core/error.h"
#include "gl/pass_bindings.h"

namespace pn {

std::vector<Query> QueryResults::list(std::size_t image, std::size_t count) const {
  std::vector<Query> out;
  for (std::size_t k = 0; k < count; ++k) out.push_back(at(image, k));
  return out;
}

QueryBatch::QueryBatch(const Context& context, const std::vector<Image>& inputs, std::size_t results,
                       std::size_t word_results)
    : context_(&context) {
  if (inputs.empty()) throw Error("query batch: expected at least one input image");
  width_ = inputs.front().width, height_ = inputs.front().height;
  for (const Image& input : inputs) {
    if (input.width != width_ || input.height != height_)
      throw Error("query batch: input images of " + std::to_string(input.width) + "x" + std::to_string(input.height) +
                  " and " + std::to_string(width_) + "x" + std::to_string(height_) + ": expected one size");
    inputs_.push_back(upload_float_texture(context, input));
  }
  for (std::size_t i = 0; i < results; ++i) results_.push_back(make_float_texture(context, width_, height_, 4));
  for (std::size_t i = 0; i < word_results; ++i)
    word_results_.push_back(make_texture(context, GL_TEXTURE_2D, GL_RGBA32UI, width_, height_));
}

QueryResults QueryBatch::read() const {
  QueryResults out;
  for (const FloatTexture& result : results_) out.images.push_back(read_float_texture(*context_, result));
  for (const GlObject& words : word_results_)
    out.words.push_back(read_uint4_texture(*context_, words, width_, height_));
  return out;
}

QueryPass::QueryPass(const Context& context, const SourceTree& tree, const std::string& pass, QueryBindings bindings,
                     std::vector<Define> defines, QueryCompile compile)
    : context_(&context), bindings_(std::move(bindings)), defines_(std::move(defines)), programs_(context, tree, pass) {
  if (compile == QueryCompile::now) programs_.get(defines_);
}

void QueryPass::dispatch(const QueryBatch& batch, const std::vector<QueryTexture>& textures,
                         const QueryBlock& block) const {
  if (batch.inputs_.size() != bindings_.inputs.size() || batch.results_.size() != bindings_.results.size() ||
      batch.word_results_.size() != bindings_.word_results.size())
    throw Error("query pass: a batch of " + std::to_string(batch.inputs_.size()) + " inputs and " +
                std::to_string(batch.results_.size() + batch.word_results_.size()) +
                " results: expected one per binding of the pass");
  const ComputeProgram& program = programs_.get(defines_);
  PassBindings bind(*context_);
  if (block.data != nullptr) bind.uniform_data(block.binding, block.data, block.size);
  for (const QueryTexture& t : textures) bind.texture(t.binding, t.texture);
  for (std::size_t i = 0; i < batch.inputs_.size(); ++i) bind.texture(bindings_.inputs[i], batch.inputs_[i]);
  for (std::size_t i = 0; i < batch.results_.size(); ++i)
    bind.image(bindings_.results[i], batch.results_[i], GL_WRITE_ONLY, GL_RGBA32F);
  for (std::size_t i = 0; i < batch.word_results_.size(); ++i)
    bind.image(bindings_.word_results[i], batch.word_results_[i], GL_WRITE_ONLY, GL_RGBA32UI);
  program.dispatch(batch.width_, batch.height_);
}

QueryResults QueryPass::run(const std::vector<Image>& inputs, const std::vector<QueryTexture>& textures,
                            const QueryBlock& block) const {
  const QueryBatch batch(*context_, inputs, bindings_.results.size(), bindings_.word_results.size());
  dispatch(batch, textures, block);
  return batch.read();
}

QueryResults QueryPass::run(const std::vector<std::vector<Query>>& inputs, const std::vector<QueryTexture>& textures,
                            const QueryBlock& block) const {
  std::vector<Image> images;
  for (const std::vector<Query>& list : inputs) images.push_back(query_image(list));
  return run(images, textures, block);
}

}  // namespace pn
