// Runner side of glsl/passes/region_query.comp.
#pragma once

#include "core/image.h"
#include "pass_runners/query_pass.h"
#include "shader/source_tree.h"

namespace pn {

class RegionQuery {
 public:
  RegionQuery(const QueryDevice& device, const SourceTree& tree);

  // `queries` is RGBA (x, y, side, -) per texel; returns RGBA (u, v, side, level).
  // Throws Error for map_size < 1.
  Image run(const Image& queries, int map_size, bool centred) const;
  // `queries` RGBA (x, y, side, t); returns region_query.comp's four area results (its header).
  Image run_areas(const Image& queries, int map_size) const;

 private:
  QueryPass query_;
};

}  // namespace pn
