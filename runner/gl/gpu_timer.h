// GPU time of a stretch of GL work from a pair of GL_TIMESTAMP queries
// (SPEC §8: on llvmpipe GL_TIME_ELAPSED around a dispatch reads 0, timestamps
// do measure it), with the wall time to glFinish alongside as a sanity check.
// Timestamps are GL 4.5 core; on OpenGL ES they need GL_EXT_disjoint_timer_query. Without it,
// or when the extension reports the interval disjoint, a GPU time is NaN ("unavailable"), never
// made up; the wall time is always measured.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "gl/objects.h"

namespace pn {

struct StageTime {
  double gpu_ms = 0.0;   // between the two timestamps; NaN where the context has no timer queries
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

// GPU time of consecutive stages of one run, without waiting between them: a
// GL_TIMESTAMP query at each stage boundary, read back once at the end.
class StageClock {
 public:
  explicit StageClock(const Context& context);
  void start();                        // marks the beginning of the first stage
  void stage(const std::string& name);  // marks the end of the stage `name`
  // (name, GPU milliseconds) of every stage in order (NaN without timer queries); waits for the GPU.
  std::vector<std::pair<std::string, double>> read() const;

 private:
  const Context* context_;
  std::vector<GlObject> marks_;
  std::vector<std::string> names_;
};

// Median of a non-empty list (the mean of the two middle values for an even count); NaN if any
// value is NaN (a GPU time that was unavailable).
double median(std::vector<double> values);

}  // namespace pn
