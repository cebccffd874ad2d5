#include "gl/gpu_timer.h"

#include <algorithm>
#include <chrono>
#include <vector>

#include "core/error.h"

namespace pn {

GpuTimer::GpuTimer(const Context& context)
    : context_(&context),
      begin_(context, GlKind::query, GL_TIMESTAMP),
      end_(context, GlKind::query, GL_TIMESTAMP) {}

StageTime GpuTimer::measure(const std::function<void()>& work) const {
  const auto& gl = context_->gl();
  gl.Finish();
  const auto start = std::chrono::steady_clock::now();
  gl.QueryCounter(begin_.id(), GL_TIMESTAMP);
  work();
  gl.QueryCounter(end_.id(), GL_TIMESTAMP);
  gl.Finish();
  const auto stop = std::chrono::steady_clock::now();
  GLuint64 t0 = 0, t1 = 0;
  gl.GetQueryObjectui64v(begin_.id(), GL_QUERY_RESULT, &t0);
  gl.GetQueryObjectui64v(end_.id(), GL_QUERY_RESULT, &t1);
  context_->throw_if_gl_error("timestamp queries");
  return {static_cast<double>(t1 - t0) * 1e-6, std::chrono::duration<double, std::milli>(stop - start).count()};
}

StageClock::StageClock(const Context& context) : context_(&context) {}

void StageClock::start() {
  marks_.clear();
  names_.clear();
  marks_.emplace_back(*context_, GlKind::query, GL_TIMESTAMP);
  context_->gl().QueryCounter(marks_.back().id(), GL_TIMESTAMP);
}

void StageClock::stage(const std::string& name) {
  if (marks_.empty()) throw Error("StageClock: stage '" + name + "' before start()", ExitCode::failed);
  marks_.emplace_back(*context_, GlKind::query, GL_TIMESTAMP);
  context_->gl().QueryCounter(marks_.back().id(), GL_TIMESTAMP);
  names_.push_back(name);
}

std::vector<std::pair<std::string, double>> StageClock::read() const {
  const auto& gl = context_->gl();
  std::vector<GLuint64> t(marks_.size(), 0);
  for (size_t i = 0; i < marks_.size(); ++i) gl.GetQueryObjectui64v(marks_[i].id(), GL_QUERY_RESULT, &t[i]);
  context_->throw_if_gl_error("timestamp queries");
  std::vector<std::pair<std::string, double>> out;
  for (size_t i = 0; i < names_.size(); ++i) out.emplace_back(names_[i], static_cast<double>(t[i + 1] - t[i]) * 1e-6);
  return out;
}

double median(std::vector<double> values) {
  if (values.empty()) throw Error("median of no values", ExitCode::failed);
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace pn
