// Runner side of glsl/passes/cascades_query.comp: cascades.h and
// cascades.glsl's functions over a batch of queries. The caller fills the
// block (PnCascadesQueryParams: which function, and the settings the batch shares).
#pragma once

#include <vector>

#include "pass_runners/query_pass.h"

namespace pn {

class CascadesQueryPass {
 public:
  CascadesQueryPass(const QueryDevice& device, const SourceTree& tree);
  // One result per query.
  std::vector<Query> run(const QueryBlock& block, const std::vector<Query>& queries) const;

 private:
  QueryPass query_;
};

}  // namespace pn
