#include "passes/export_pass.h"

#include "exports/exports.h"

namespace pn {

ExportPass::ExportPass(const QueryDevice& device, const SourceTree& tree, const std::string& module,
                       const std::vector<Define>& defines)
    : query_(device, tree, "exports/" + module + ".comp",
             {{PN_EXPORT_RECEIVERS_BINDING, PN_EXPORT_PLANES_BINDING}, {PN_EXPORT_VISIBILITY_IMAGE}, {}}, defines) {}

std::vector<float> ExportPass::run(const std::vector<QueryTexture>& textures,
                                   const std::vector<ExportReceiver>& receivers, const QueryBlock& block) const {
  if (receivers.empty()) return {};
  std::vector<Query> a, b;
  for (const ExportReceiver& r : receivers) {
    a.push_back({r.u, r.v, r.depth, r.plane ? 1.0f : 0.0f});
    b.push_back({r.du, r.dv, 0.0f, 0.0f});
  }
  const QueryResults results = query_.run({a, b}, textures, block);
  std::vector<float> out;
  for (const Query& q : results.list(0, receivers.size())) out.push_back(q[0]);
  return out;
}

}  // namespace pn
