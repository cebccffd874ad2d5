// GPU time of a stretch of GL work from a pair of GL_TIMESTAMP queries
// (SPEC §8: on llvmpipe GL_TIME_ELAPSED around a dispatch reads 0, timestamps
// do measure it), with the wall time to glFinish alongside as a sanity check.
#pragma once

#include <functional>
#include <vector>

#include "gl/objects.h"

namespace pn {

struct StageTime {
  double gpu_ms = 0.0;   // between the two timestamps
  double wall_ms = 0.0;  // CPU clock from before the work to after glFinish
};

class GpuTimer {
 public:
  explicit GpuTimer(const Context& context);
  StageTime measure(const std::function<void()>& work) const;

 private:
  const Context* context_;
  GlObject begin_, end_;
};

// Median of a non-empty list (the mean of the two middle values for an even count).
double median(std::vector<double> values);

}  // namespace pn
