// Runner side of glsl/passes/receiver_plane_query.comp: receiver_plane.glsl's
// gradient from G-buffer neighbours, its range over a rectangle and the thresholds it gives, over a batch.
#pragma once

#include <array>
#include <vector>

#include "pass_runners/query_pass.h"
#include "shader/source_tree.h"

namespace pn {

struct ReceiverPlaneGpuQuery {
  std::array<Query, 5> entries;  // centre, left, right, below, above: (u, v, d, valid)
  float max_slope = 0.0f;
  int origin_x = 0, origin_y = 0, size_x = 1, size_y = 1;
  float gradient_x = 0.0f, gradient_y = 0.0f;  // the range's
};

struct ReceiverPlaneGpuResult {
  float gradient_x = 0.0f, gradient_y = 0.0f;  // pnReceiverPlaneFromNeighbours
  float lo = 0.0f, hi = 0.0f;                  // pnReceiverPlaneRange
  // With the receiver's depth the threshold: pnReceiverPlaneThreshold at the rectangle's last texel,
  // pnReceiverPlaneThresholdRange over the rectangle.
  float threshold = 0.0f, threshold_lo = 0.0f, threshold_hi = 0.0f;
};

class ReceiverPlaneQueryPass {
 public:
  ReceiverPlaneQueryPass(const QueryDevice& device, const SourceTree& tree);
  std::vector<ReceiverPlaneGpuResult> run(const std::vector<ReceiverPlaneGpuQuery>& queries) const;

 private:
  QueryPass query_;
};

}  // namespace pn
