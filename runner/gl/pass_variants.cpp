#include "gl/pass_variants.h"

#include <utility>

namespace pn {

PassVariants::PassVariants(const Context& context, const SourceTree& tree, std::string pass)
    : context_(&context), tree_(tree), pass_(std::move(pass)) {}

const ComputeProgram& PassVariants::get(const std::vector<Define>& defines) const {
  const std::string key = define_key(defines);
  auto found = programs_.find(key);
  if (found == programs_.end())
    found = programs_.emplace(key, std::make_unique<ComputeProgram>(compile_pass(*context_, tree_, pass_, defines))).first;
  return *found->second;
}

}  // namespace pn
