#include "device/program_variants.h"

#include <utility>

namespace pn {

ProgramVariants::ProgramVariants(const QueryDevice& device, const SourceTree& tree, std::string pass)
    : device_(&device), tree_(tree), pass_(std::move(pass)) {}

const QueryProgram& ProgramVariants::get(const std::vector<Define>& defines) const {
  std::unique_ptr<QueryProgram>& made = made_[define_key(defines)];
  if (!made) made = device_->compile_query(tree_, pass_, defines);
  return *made;
}

}  // namespace pn
