#include "pass_runners/cascades_query_pass.h"

#include "gl/std140.h"

namespace pn::glsl {
#include "passes/cascades_query.h"
}  // namespace pn::glsl

namespace pn {

CascadesQueryPass::CascadesQueryPass(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/cascades_query.comp",
             {{PN_CASCADES_QUERY_QUERIES_BINDING}, {PN_CASCADES_QUERY_RESULTS_BINDING}}) {}

std::vector<Query> CascadesQueryPass::run(const QueryBlock& block, const std::vector<Query>& queries) const {
  return query_.run({queries}, {}, block).list(0, queries.size());
}

}  // namespace pn
