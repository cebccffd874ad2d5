// Runner side of glsl/passes/savsm_shade.comp (the savsm technique's
// visibility per screen pixel) and glsl/passes/savsm_query.comp (savsm.glsl's
// estimate for a batch of receivers, every step's value and its fetch count:
// the check's query pass). Both compiled once per table kind.
#pragma once

#include <vector>

#include "pass_runners/minmax_mip_pass.h"
#include "pass_runners/query_pass.h"
#include "pass_runners/summed_area_pass.h"
#include "core/texel_rect.h"
#include "modules/savsm_face.h"
#include "scene/light_model.h"
#include "pass_runners/shade_pass.h"
#include "shader/source_tree.h"

namespace pn {

// What savsm.glsl returns for one receiver (PnSavsm), and the fetches it took.
struct SavsmQueryResult {
  Rect search, filter;
  float blocker = 0.0f;
  bool has_blocker = false;
  float filter_side = 0.0f;
  float fetches = 0.0f;
  float mean = 0.0f, variance = 0.0f, chebyshev = 1.0f, visibility = 1.0f;
};

class SavsmPass {
 public:
  SavsmPass(const QueryDevice& device, const SourceTree& tree);

  // Per screen pixel of a G-buffer (screen² RGBA32F: u, v in texels, light depth, valid), as a new
  // screen² R32F texture; pixels without a surface are 1. `mip`: the map's min/max mip chain
  // (read when settings.bound or the min blocker mode; else any 2-D texture).
  // In `stage`: savsm.glsl's pnSavsm in a compute pass or a fragment shader (shade_pass.h).
  std::unique_ptr<DeviceTexture> shade(const MomentsTable& table, const DeviceTexture& mip,
                                       const DeviceTexture& gbuffer, int screen_size, const LightModel& light,
                                       const SavsmSettings& settings, ShadeStage stage = ShadeStage::compute) const;

 private:
  ShadePass shade_;  // by PN_SAVSM_TABLE
};

// savsm.glsl's pnSavsm over a batch of receivers (the check's query pass), on any executor.
class SavsmQueryPass {
 public:
  SavsmQueryPass(const QueryDevice& device, const SourceTree& tree);
  // One result per receiver (u, v in texels, linear light depth).
  std::vector<SavsmQueryResult> query(const MomentsTable& table, const DeviceTexture& mip,
                                      const std::vector<SavsmReceiver>& receivers, const LightModel& light,
                                      const SavsmSettings& settings) const;

 private:
  QueryPass fixed_query_, float_query_;  // PN_SAVSM_TABLE fixed, float
};

}  // namespace pn
