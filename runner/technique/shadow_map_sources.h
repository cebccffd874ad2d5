// The catalogue of shadow-map sources (frame/shadow_map_source.h): one entry a
// kind, found by the name render, bench and check take from the user.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "frame/shadow_map_source.h"

namespace pn {

struct ShadowMapSourceEntry {
  const char* name;
  const char* summary;
  std::unique_ptr<ShadowMapSource> (*make)(const QueryDevice& device, const SourceTree& tree, const SourceOptions& options);
};

const std::vector<ShadowMapSourceEntry>& shadow_map_sources();

// Throws Error naming `name` and listing the sources.
const ShadowMapSourceEntry& find_shadow_map_source(const std::string& name);

}  // namespace pn
