#include "pass_runners/sample_table_query_pass.h"

#include "passes/correlated_multi_jitter_query.h"
#include "passes/sample_table_query.h"

namespace pn {

SampleTableQueryPass::SampleTableQueryPass(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/sample_table_query.comp",
             {{PN_SAMPLE_TABLE_QUERY_QUERIES_BINDING},
              {PN_SAMPLE_TABLE_QUERY_RESULT_A_BINDING, PN_SAMPLE_TABLE_QUERY_RESULT_B_BINDING}}) {}

std::vector<Image> SampleTableQueryPass::run(const SampleTable& table, const Image& queries) const {
  const std::unique_ptr<DeviceTexture> table_texture = query_.device().upload(table.image());
  return query_.run(std::vector<Image>{queries}, {{PN_SAMPLE_TABLE_QUERY_TABLE_BINDING, *table_texture}}).images;
}

CorrelatedMultiJitterQueryPass::CorrelatedMultiJitterQueryPass(const QueryDevice& device, const SourceTree& tree)
    : query_(device, tree, "passes/correlated_multi_jitter_query.comp",
             {{PN_CMJ_QUERY_QUERIES_BINDING}, {PN_CMJ_QUERY_RESULTS_BINDING}}) {}

Image CorrelatedMultiJitterQueryPass::run(const Image& queries) const {
  return query_.run(std::vector<Image>{queries}).images.front();
}

}  // namespace pn
