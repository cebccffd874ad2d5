#include "check/compare.h"

#include <cfloat>
#include <cmath>
#include <limits>

#include "core/format.h"

namespace pn {
namespace {

std::string number(double v) { return format_number("%.9g", v); }
std::string short_number(double v) { return format_number("%.2e", v); }

// Per-element measure of a tolerance: relative for relative bounds, absolute otherwise.
Tolerance::Kind element_kind(const Tolerance& t) {
  return t.kind == Tolerance::Kind::relative ? Tolerance::Kind::relative : Tolerance::Kind::absolute;
}

double element_error(float e, float o, Tolerance::Kind kind) {
  const bool ef = std::isfinite(e), of = std::isfinite(o);
  if (!ef || !of) {
    const bool same = (std::isnan(e) && std::isnan(o)) || (!std::isnan(e) && e == o);
    return same ? 0.0 : std::numeric_limits<double>::infinity();
  }
  const double diff = std::fabs(static_cast<double>(e) - static_cast<double>(o));
  if (kind == Tolerance::Kind::relative) return diff / std::max(std::fabs(static_cast<double>(e)), double(FLT_MIN));
  return diff;
}

}  // namespace

std::string Tolerance::describe() const {
  switch (kind) {
    case Kind::absolute: return bound == 0.0 ? "exact" : "abs <= " + short_number(bound);
    case Kind::relative: return "rel <= " + short_number(bound);
    case Kind::rmse: return "rmse <= " + short_number(bound);
  }
  return "?";
}

std::string Comparison::where(const Tolerance& tolerance) const {
  if (!problem.empty()) return problem;
  if (x < 0) return "no elements";
  std::string out = "at (" + std::to_string(x) + ", " + std::to_string(y) + ")";
  if (channel != 0) out += "[" + std::to_string(channel) + "]";
  const char* measure = tolerance.kind == Tolerance::Kind::relative ? "rel" : "abs";
  // The error as the comparison measured it (in double where the expected value was a double, which
  // `expected` only shows rounded to float), except under an RMSE bound, where worst_error is the RMSE.
  const double error = tolerance.kind == Tolerance::Kind::rmse
                           ? element_error(expected, observed, element_kind(tolerance))
                           : worst_error;
  out += ": expected " + number(expected) + ", observed " + number(observed) + " (" + measure + " error " +
         short_number(error) +
         (pass ? ", within " : ", not within ") + tolerance.describe() + ")";
  if (tolerance.kind == Tolerance::Kind::rmse) out += ", rmse " + short_number(rmse);
  return out;
}

Comparison compare(const Image& expected, const Image& observed, const Tolerance& tolerance) {
  Comparison c;
  if (expected.width != observed.width || expected.height != observed.height ||
      expected.channels != observed.channels) {
    c.problem = "size mismatch: expected " + std::to_string(expected.width) + "x" + std::to_string(expected.height) +
                "x" + std::to_string(expected.channels) + ", observed " + std::to_string(observed.width) + "x" +
                std::to_string(observed.height) + "x" + std::to_string(observed.channels);
    c.worst_error = std::numeric_limits<double>::infinity();
    return c;
  }
  const Tolerance::Kind kind = element_kind(tolerance);
  double worst = -1.0, square_sum = 0.0;
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      for (int ch = 0; ch < expected.channels; ++ch) {
        const float e = expected.at(x, y, ch), o = observed.at(x, y, ch);
        const double err = element_error(e, o, kind);
        square_sum += err * err;
        if (err > worst) {
          worst = err;
          c.x = x, c.y = y, c.channel = ch, c.expected = e, c.observed = o;
        }
      }
    }
  }
  const double count = static_cast<double>(expected.texels.size());
  c.rmse = count > 0 ? std::sqrt(square_sum / count) : 0.0;
  c.worst_error = tolerance.kind == Tolerance::Kind::rmse ? c.rmse : std::max(worst, 0.0);
  c.pass = c.worst_error <= tolerance.bound;
  return c;
}

void BoundedElements::add(double e, float o, double bound, int x, int y, int channel) {
  expected.push_back(e);
  observed.push_back(o);
  bounds.push_back(bound);
  where.push_back({x, y, channel});
}

void BoundedElements::add_interval(double lo, double hi, float o, int x, int y, int channel) {
  add(0.5 * (lo + hi), o, 0.5 * (hi - lo), x, y, channel);
}

Comparison compare_bounded(const BoundedElements& elements, Tolerance& tolerance) {
  Comparison c;
  c.pass = true;
  double worst_ratio = -1.0, worst_bound = 0.0, square_sum = 0.0;
  for (size_t i = 0; i < elements.expected.size(); ++i) {
    const double e = elements.expected[i], o = elements.observed[i], b = elements.bounds[i];
    const double err = std::isfinite(o) ? std::fabs(o - e) : std::numeric_limits<double>::infinity();
    const double ratio = b > 0.0 ? err / b : (err > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
    c.pass = c.pass && err <= b;
    if (std::isfinite(err)) square_sum += err * err;
    if (ratio > worst_ratio) {
      worst_ratio = ratio, worst_bound = b;
      c.x = elements.where[i][0], c.y = elements.where[i][1], c.channel = elements.where[i][2];
      c.expected = static_cast<float>(e), c.observed = static_cast<float>(o), c.worst_error = err;
    }
  }
  const size_t n = elements.expected.size();
  c.rmse = n == 0 ? 0.0 : std::sqrt(square_sum / static_cast<double>(n));
  tolerance = Tolerance::absolute(worst_bound);
  return c;
}

}  // namespace pn
