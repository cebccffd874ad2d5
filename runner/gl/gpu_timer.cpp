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

double median(std::vector<double> values) {
  if (values.empty()) throw Error("median of no values", ExitCode::failed);
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace pn
