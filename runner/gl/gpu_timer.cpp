#include "gl/gpu_timer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.h"

namespace pn {
namespace {

constexpr double kUnavailable = std::numeric_limits<double>::quiet_NaN();

// GL_EXT_disjoint_timer_query's flag (ES only): set when something (a clock change, a power
// state) made the timestamps since the last read meaningless; reading it clears it.
bool timestamps_disjoint(const Context& context) {
  if (!context.is_es()) return false;
  constexpr GLenum kGpuDisjoint = 0x8FBB;  // GL_GPU_DISJOINT_EXT
  GLint disjoint = 0;
  context.gl().GetIntegerv(kGpuDisjoint, &disjoint);
  return disjoint != 0;
}

}  // namespace

GpuTimer::GpuTimer(const Context& context)
    : context_(&context),
      begin_(context, GlKind::query, GL_TIMESTAMP),
      end_(context, GlKind::query, GL_TIMESTAMP) {}

StageTime GpuTimer::measure(const std::function<void()>& work) const {
  const auto& gl = context_->gl();
  const bool timed = context_->has_timer_queries();
  gl.Finish();
  if (timed) timestamps_disjoint(*context_);  // clears the flag
  const auto start = std::chrono::steady_clock::now();
  if (timed) gl.QueryCounter(begin_.id(), GL_TIMESTAMP);
  work();
  if (timed) gl.QueryCounter(end_.id(), GL_TIMESTAMP);
  gl.Finish();
  const auto stop = std::chrono::steady_clock::now();
  const double wall_ms = std::chrono::duration<double, std::milli>(stop - start).count();
  if (!timed) return {kUnavailable, wall_ms};
  GLuint64 t0 = 0, t1 = 0;
  gl.GetQueryObjectui64v(begin_.id(), GL_QUERY_RESULT, &t0);
  gl.GetQueryObjectui64v(end_.id(), GL_QUERY_RESULT, &t1);
  context_->throw_if_gl_error("timestamp queries");
  if (timestamps_disjoint(*context_)) return {kUnavailable, wall_ms};
  return {static_cast<double>(t1 - t0) * 1e-6, wall_ms};
}

StageClock::StageClock(const Context& context) : context_(&context) {}

void StageClock::start() {
  marks_.clear();
  names_.clear();
  marks_.emplace_back(*context_, GlKind::query, GL_TIMESTAMP);
  if (!context_->has_timer_queries()) return;
  timestamps_disjoint(*context_);  // clears the flag
  context_->gl().QueryCounter(marks_.back().id(), GL_TIMESTAMP);
}

void StageClock::stage(const std::string& name) {
  if (marks_.empty()) throw Error("StageClock: stage '" + name + "' before start()", ExitCode::failed);
  marks_.emplace_back(*context_, GlKind::query, GL_TIMESTAMP);
  if (context_->has_timer_queries()) context_->gl().QueryCounter(marks_.back().id(), GL_TIMESTAMP);
  names_.push_back(name);
}

std::vector<std::pair<std::string, double>> StageClock::read() const {
  const auto& gl = context_->gl();
  std::vector<std::pair<std::string, double>> out;
  if (!context_->has_timer_queries()) {
    for (const std::string& name : names_) out.emplace_back(name, kUnavailable);
    return out;
  }
  std::vector<GLuint64> t(marks_.size(), 0);
  for (size_t i = 0; i < marks_.size(); ++i) gl.GetQueryObjectui64v(marks_[i].id(), GL_QUERY_RESULT, &t[i]);
  context_->throw_if_gl_error("timestamp queries");
  const bool disjoint = timestamps_disjoint(*context_);
  for (size_t i = 0; i < names_.size(); ++i)
    out.emplace_back(names_[i], disjoint ? kUnavailable : static_cast<double>(t[i + 1] - t[i]) * 1e-6);
  return out;
}

double median(std::vector<double> values) {
  if (values.empty()) throw Error("median of no values", ExitCode::failed);
  for (double v : values)
    if (std::isnan(v)) return v;  // an unavailable time stays unavailable (and NaN cannot be sorted)
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace pn
