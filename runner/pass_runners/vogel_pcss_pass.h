// Runner side of glsl/passes/vogel_pcss_query.comp: vogel_pcss.glsl's disk
// (pnVogelOcclusion) and its rotation noise (pnInterleavedGradientNoise) over
// a batch of queries.
#pragma once

#include <vector>

#include "pass_runners/query_pass.h"
#include "shader/source_tree.h"

namespace pn {

struct VogelPcssGpuQuery {
  float centre_x = 0.0f, centre_y = 0.0f, diameter = 0.0f;  // texels
  float receiver_depth = 0.0f, bias = 0.0f;
  int count = 0;
  float turn = 0.0f;
  float gradient_x = 0.0f, gradient_y = 0.0f;  // the receiver plane's (0: a constant bias)
  // The result's noise from the one call instead: pnVogelPcssEstimate's turn at the pixel
  // ivec2(centre) (a light of its own, the defaults with this bias).
  bool estimate_turn = false;
};

struct VogelPcssGpuResult {
  float occluders = 0.0f, depth_sum = 0.0f, samples = 0.0f;
  float noise = 0.0f;  // pnInterleavedGradientNoise(centre), or pnVogelPcssEstimate's turn (estimate_turn)
};

class VogelPcssQueryPass {
 public:
  VogelPcssQueryPass(const QueryDevice& device, const SourceTree& tree);
  std::vector<VogelPcssGpuResult> run(const DeviceTexture& depth_map, const std::vector<VogelPcssGpuQuery>& queries) const;

 private:
  QueryPass query_;
};

}  // namespace pn
