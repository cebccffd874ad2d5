#include "pass_runners/export_pass.h"

#include <cmath>

#include "exports/exports.h"

namespace pn {

ExportPass::ExportPass(const QueryDevice& device, const SourceTree& tree, const std::string& module,
                       std::vector<Define> defines)
    : device_(&device), defines_(std::move(defines)), pass_(device, tree, "exports/" + module, PN_EXPORT_VISIBILITY_IMAGE) {}

int ExportPass::side(std::size_t count) {
  int s = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count)))));
  while (static_cast<std::size_t>(s) * static_cast<std::size_t>(s) < count) ++s;  // sqrt's rounding
  return s;
}

std::pair<int, int> ExportPass::texel(std::size_t k, std::size_t count) {
  const std::size_t s = static_cast<std::size_t>(side(count));
  return {static_cast<int>(k % s), static_cast<int>(k / s)};
}

std::vector<float> ExportPass::run(ShadeStage stage, const std::vector<QueryTexture>& textures,
                                   const std::vector<ExportReceiver>& receivers, const QueryBlock& block) const {
  if (receivers.empty()) return {};
  const int s = side(receivers.size());
  // The texels past the last receiver repeat the first: every invocation makes a valid call.
  Image a(s, s, 4), b(s, s, 4);
  for (int k = 0; k < s * s; ++k) {
    const ExportReceiver& r = receivers[static_cast<std::size_t>(k) < receivers.size() ? k : 0];
    const float av[4] = {r.u, r.v, r.depth, r.plane ? 1.0f : 0.0f}, bv[4] = {r.du, r.dv, 0.0f, 0.0f};
    for (int c = 0; c < 4; ++c) a.at(k % s, k / s, c) = av[c], b.at(k % s, k / s, c) = bv[c];
  }
  const std::unique_ptr<DeviceTexture> receiver_image = device_->upload(a), plane_image = device_->upload(b);
  PassResources resources;
  for (const QueryTexture& t : textures) resources.textures.push_back(t);
  resources.add_textures({{PN_EXPORT_RECEIVERS_BINDING, *receiver_image}, {PN_EXPORT_PLANES_BINDING, *plane_image}});
  resources.block = block;
  const Image visibility = device_->read_texture(*pass_.run(stage, defines_, s, resources), 0, 0);
  std::vector<float> out;
  for (std::size_t k = 0; k < receivers.size(); ++k) {
    const auto [x, y] = texel(k, receivers.size());
    out.push_back(visibility.at(x, y));
  }
  return out;
}

}  // namespace pn
