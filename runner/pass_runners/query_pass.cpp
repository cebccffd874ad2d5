#include "pass_runners/query_pass.h"

namespace pn {

QueryPass::QueryPass(const QueryDevice& device, const SourceTree& tree, const std::string& pass,
                     QueryBindings bindings, std::vector<Define> defines, QueryCompile compile)
    : device_(&device), tree_(tree), pass_(pass), bindings_(std::move(bindings)), defines_(std::move(defines)) {
  if (compile == QueryCompile::now) program();
}

const QueryProgram& QueryPass::program() const {
  if (!program_) program_ = device_->compile_query(tree_, pass_, defines_);
  return *program_;
}

std::unique_ptr<QueryBatch> QueryPass::batch(const std::vector<Image>& inputs) const {
  return device_->make_batch(inputs, bindings_.results.size(), bindings_.word_results.size());
}

void QueryPass::dispatch(const QueryBatch& batch, const std::vector<QueryTexture>& textures,
                         const QueryBlock& block) const {
  device_->dispatch(program(), bindings_, batch, textures, block);
}

QueryResults QueryPass::run(const std::vector<Image>& inputs, const std::vector<QueryTexture>& textures,
                            const QueryBlock& block) const {
  const std::unique_ptr<QueryBatch> b = batch(inputs);
  dispatch(*b, textures, block);
  return b->read();
}

QueryResults QueryPass::run(const std::vector<std::vector<Query>>& inputs, const std::vector<QueryTexture>& textures,
                            const QueryBlock& block) const {
  std::vector<Image> images;
  for (const std::vector<Query>& list : inputs) images.push_back(query_image(list));
  return run(images, textures, block);
}

}  // namespace pn
