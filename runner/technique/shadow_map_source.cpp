#include "technique/shadow_map_source.h"

#include "core/error.h"

namespace pn {

const std::vector<ShadowMapSourceEntry>& shadow_map_sources() {
  static const std::vector<ShadowMapSourceEntry> sources{
      {"full", "every triangle drawn into a new map each frame",
       [](const Context& context, const SourceTree& tree) -> std::unique_ptr<ShadowMapSource> {
         return std::make_unique<FullRenderSource>(context, tree);
       }},
  };
  return sources;
}

const ShadowMapSourceEntry& find_shadow_map_source(const std::string& name) {
  std::string known;
  for (const ShadowMapSourceEntry& e : shadow_map_sources()) {
    if (name == e.name) return e;
    known += (known.empty() ? "" : ", ") + std::string(e.name);
  }
  throw Error("unknown shadow-map source '" + name + "': expected one of " + known);
}

}  // namespace pn
