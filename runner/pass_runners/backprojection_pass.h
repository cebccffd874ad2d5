// Runner side of glsl/passes/backprojection_query.comp: backprojection.glsl's
// pnBackprojectionWork (with or without a second layer) over a batch of
// receivers, on any executor.
#pragma once

#include <vector>

#include "backprojection.h"
#include "pass_runners/minmax_mip_pass.h"
#include "pass_runners/query_pass.h"
#include "scene/light_model.h"
#include "shader/source_tree.h"

namespace pn {

struct BackprojectionQuery {
  float u = 0.0f, v = 0.0f, depth = 0.0f;  // the receiver (texels, linear light depth)
  float bias = 0.0f;
  int side = PN_BACKPROJECTION_DEFAULT_SIDE;                  // side × side light samples
  float tolerance = 0.0f;                                     // 0: every texel resolved
  int budget = PN_BACKPROJECTION_DEFAULT_BUDGET;              // nodes
  float gap = static_cast<float>(PN_BACKPROJECTION_DEFAULT_GAP);  // texel widths: neighbours of one surface
  float thickness = static_cast<float>(PN_BACKPROJECTION_DEFAULT_THICKNESS);  // a silhouette's wall, of dP - d
};

struct BackprojectionResult {
  float visibility = 1.0f, blocked = 0.0f, nodes = 0.0f, patches = 0.0f;
};

class BackprojectionQueryPass {
 public:
  BackprojectionQueryPass(const QueryDevice& device, const SourceTree& tree);
  // Throws Error when a chain is not of the light's map size. With `second_mip` (the min/max chain
  // of the map's second layer), the call over slabs (pnBackprojectionWork's overload with it).
  std::vector<BackprojectionResult> run(const MinMaxMipChain& mip, const LightModel& light,
                                        const std::vector<BackprojectionQuery>& queries,
                                        const MinMaxMipChain* second_mip = nullptr) const;

 private:
  QueryPass query_;
};

}  // namespace pn
