// Cases of the receiver_plane check: glsl/receiver_plane.glsl through
// passes/receiver_plane_query.comp against receiver_plane_reference (the
// definition in double). Receivers anywhere in a 2048² map at depths 1..50 on
// random planes (up to 0.2 light depth a texel), their four G-buffer
// neighbours a random 0.2..4 texels away along two screen directions; one in
// seven neighbours invalid, one in seven off the plane by 5..20 (a depth
// edge: the step must come from the other side), one query in ten with
// parallel steps (g = 0), slopes clamped at 0.05, 0.5 or 10. The
// range over rectangles of 1..48 texels a side against every texel centre.
//
// Tolerances (u = 2^-24). The steps are float differences of the entries
// (each component within u (|p| + |c|) of the double step); the gradient by
// Cramer's rule is then within
//   (e_num + |g| e_det) / |det| + 4u |g|  per component,
//   e_num = 2u (|a.d b.v| + |b.d a.v|) + δa.d |b.v| + |a.d| δb.v + δb.d |a.v| + |b.d| δa.v,
//   e_det the same for a.u b.v - a.v b.u,
// twice that for the clamp's rescaling; a query whose |det| lies within e_det
// of the parallel steps' bound (PN_RECEIVER_PLANE_MIN_SINE |a| |b|) is left out (counted). The range: within
// 8u (|d| + |g.x| (|o.x| + s.x + |u| + 1) + |g.y| (|o.y| + s.y + |v| + 1)).
#include <algorithm>
#include <cmath>
#include <string>

#include "check/module_check.h"
#include "core/seeded_random.h"
#include "pass_runners/receiver_plane_pass.h"
#include "receiver_plane.h"
#include "reference/receiver_plane_reference.h"

namespace pn {
namespace {

constexpr double kUnit = 1.0 / 16777216.0;  // u = 2^-24

Entry4 entry(const Query& q) { return {q[0], q[1], q[2], q[3]}; }

// Per component, how far the float step may be from the double one.
Step3 step_error(const Entry4& centre, const Entry4& minus, const Entry4& plus) {
  const Step3 s = receiver_plane_step(centre, minus, plus);
  const Entry4& other = s == receiver_plane_step(centre, minus, Entry4{0, 0, 0, 0}) && minus[3] != 0.0 ? minus : plus;
  Step3 e{};
  for (int i = 0; i < 3; ++i) e[i] = kUnit * (std::fabs(centre[i]) + std::fabs(other[i]));
  return e;
}

}  // namespace

std::vector<CaseResult> run_receiver_plane_check(const CheckEnvironment& env) {
  const ReceiverPlaneQueryPass pass(env.device, env.tree);
  SeededRandom random(0x5eed0025u);
  std::vector<ReceiverPlaneGpuQuery> queries;
  for (int k = 0; k < 2000; ++k) {
    const float gx = random.uniform_float(-0.2f, 0.2f), gy = random.uniform_float(-0.2f, 0.2f);
    const float u = random.uniform_float(0.0f, 2048.0f), v = random.uniform_float(0.0f, 2048.0f);
    const float d = random.uniform_float(1.0f, 50.0f);
    const auto unit_step = [&] {
      const float angle = random.uniform_float(0.0f, 6.2831853f), length = random.uniform_float(0.2f, 4.0f);
      return std::array<float, 2>{length * std::cos(angle), length * std::sin(angle)};
    };
    const std::array<float, 2> sx = unit_step();
    std::array<float, 2> sy = unit_step();
    if (k % 10 == 9) sy = {sx[0] * 0.5f, sx[1] * 0.5f};  // collinear: singular
    const auto neighbour = [&](const std::array<float, 2>& s, float sign) {
      const float scale = sign * random.uniform_float(0.8f, 1.2f);
      const float nu = u + scale * s[0], nv = v + scale * s[1];
      float nd = d + gx * (nu - u) + gy * (nv - v);
      const int kind = static_cast<int>(random.uniform_float(0.0f, 7.0f));
      if (kind == 0) return Query{nu, nv, nd, 0.0f};  // invalid
      if (kind == 1) nd += random.uniform_float(5.0f, 20.0f);  // across a depth edge
      return Query{nu, nv, nd, 1.0f};
    };
    ReceiverPlaneGpuQuery q;
    q.entries = {Query{u, v, d, 1.0f}, neighbour(sx, -1.0f), neighbour(sx, 1.0f), neighbour(sy, -1.0f), neighbour(sy, 1.0f)};
    q.max_slope = k % 3 == 0 ? 0.05f : k % 3 == 1 ? 0.5f : 10.0f;
    q.origin_x = static_cast<int>(random.uniform_float(-10.0f, 2048.0f));
    q.origin_y = static_cast<int>(random.uniform_float(-10.0f, 2048.0f));
    q.size_x = 1 + static_cast<int>(random.uniform_float(0.0f, 48.0f));
    q.size_y = 1 + static_cast<int>(random.uniform_float(0.0f, 48.0f));
    q.gradient_x = random.uniform_float(-0.3f, 0.3f), q.gradient_y = random.uniform_float(-0.3f, 0.3f);
    queries.push_back(q);
  }
  const std::vector<ReceiverPlaneGpuResult> observed = pass.run(queries);

  BoundedElements gradients, ranges, thresholds, threshold_ranges;
  long left_out = 0, singular = 0, clamped = 0;
  for (size_t k = 0; k < queries.size(); ++k) {
    const ReceiverPlaneGpuQuery& q = queries[k];
    const Entry4 c = entry(q.entries[0]), l = entry(q.entries[1]), r = entry(q.entries[2]);
    const Entry4 b = entry(q.entries[3]), a = entry(q.entries[4]);
    const Step3 sa = receiver_plane_step(c, l, r), sb = receiver_plane_step(c, b, a);
    const Step3 ea = step_error(c, l, r), eb = step_error(c, b, a);
    const double det = sa[0] * sb[1] - sa[1] * sb[0];
    const double e_det = 2.0 * kUnit * (std::fabs(sa[0] * sb[1]) + std::fabs(sa[1] * sb[0])) + ea[0] * std::fabs(sb[1]) +
                         std::fabs(sa[0]) * eb[1] + ea[1] * std::fabs(sb[0]) + std::fabs(sa[1]) * eb[0];
    // The parallel test |det| > s |a| |b|: left out where rounding may decide it.
    const double la = std::hypot(sa[0], sa[1]), lb = std::hypot(sb[0], sb[1]);
    const double e_parallel = e_det + PN_RECEIVER_PLANE_MIN_SINE * (la * (eb[0] + eb[1]) + lb * (ea[0] + ea[1]) +
                                                                   4.0 * kUnit * la * lb);
    if (std::fabs(std::fabs(det) - PN_RECEIVER_PLANE_MIN_SINE * la * lb) <= e_parallel) {
      ++left_out;
      continue;
    }
    const std::array<double, 2> g = receiver_plane_gradient(sa, sb, q.max_slope);
    const bool is_singular = g[0] == 0.0 && g[1] == 0.0;
    singular += is_singular;
    clamped += !is_singular && std::hypot(g[0], g[1]) >= q.max_slope * (1.0 - 1e-12);
    // Numerators of Cramer's rule and their rounding.
    const double e_num_x = 2.0 * kUnit * (std::fabs(sa[2] * sb[1]) + std::fabs(sb[2] * sa[1])) +
                           ea[2] * std::fabs(sb[1]) + std::fabs(sa[2]) * eb[1] + eb[2] * std::fabs(sa[1]) +
                           std::fabs(sb[2]) * ea[1];
    const double e_num_y = 2.0 * kUnit * (std::fabs(sb[2] * sa[0]) + std::fabs(sa[2] * sb[0])) +
                           eb[2] * std::fabs(sa[0]) + std::fabs(sb[2]) * ea[0] + ea[2] * std::fabs(sb[0]) +
                           std::fabs(sa[2]) * eb[0];
    const double x = static_cast<double>(k);
    for (int i = 0; i < 2; ++i) {
      const double e_num = i == 0 ? e_num_x : e_num_y;
      const double bound = is_singular ? 0.0 : 2.0 * ((e_num + std::fabs(g[i]) * e_det) / std::fabs(det) + 4.0 * kUnit * std::fabs(g[i])) + 1e-30;
      gradients.add(g[i], i == 0 ? observed[k].gradient_x : observed[k].gradient_y, bound, static_cast<int>(x), 0, i);
    }
    const Step3 receiver{c[0], c[1], c[2]};
    const std::array<double, 2> range =
        receiver_plane_range(receiver, {q.gradient_x, q.gradient_y}, {q.origin_x, q.origin_y}, {q.size_x, q.size_y});
    const double range_bound =
        8.0 * kUnit *
        (std::fabs(c[2]) + std::fabs(q.gradient_x) * (std::fabs(q.origin_x) + q.size_x + std::fabs(c[0]) + 1.0) +
         std::fabs(q.gradient_y) * (std::fabs(q.origin_y) + q.size_y + std::fabs(c[1]) + 1.0));
    ranges.add(range[0], observed[k].lo, range_bound, static_cast<int>(x), 0, 0);
    ranges.add(range[1], observed[k].hi, range_bound, static_cast<int>(x), 0, 1);
    // The thresholds with the receiver's depth as t0: the rectangle's last texel's, and their range
    // over it (each texel's threshold capped at t0: the range's ends capped), which the module widens
    // by 2^-18 of the magnitudes (a node decided against it agrees with its texels' float thresholds):
    // within twice that.
    const double last_x = q.origin_x + q.size_x - 1, last_y = q.origin_y + q.size_y - 1;
    const double along = q.gradient_x * (last_x + 0.5 - c[0]) + q.gradient_y * (last_y + 0.5 - c[1]);
    thresholds.add(receiver_plane_threshold(c[2], along), observed[k].threshold, range_bound, static_cast<int>(x), 0, 0);
    const double widening =
        0x1p-17 * (std::fabs(c[2]) + std::fabs(0.5 * (range[0] + range[1])) +
                   std::fabs(q.gradient_x) * (std::fabs(q.origin_x) + std::fabs(q.origin_x + q.size_x) + 2.0 * std::fabs(c[0])) +
                   std::fabs(q.gradient_y) * (std::fabs(q.origin_y) + std::fabs(q.origin_y + q.size_y) + 2.0 * std::fabs(c[1])));
    threshold_ranges.add(std::min(range[0], c[2]), observed[k].threshold_lo, widening + range_bound,
                         static_cast<int>(x), 0, 0);
    threshold_ranges.add(std::min(range[1], c[2]), observed[k].threshold_hi, widening + range_bound,
                         static_cast<int>(x), 0, 1);
  }
  std::vector<CaseResult> results;
  const auto add = [&](const std::string& name, const BoundedElements& elements) {
    Tolerance tolerance = Tolerance::absolute(0.0);
    const Comparison c = compare_bounded(elements, tolerance);
    results.push_back({name, tolerance, c});
  };
  const std::string n = std::to_string(queries.size() - static_cast<size_t>(left_out));
  add("pnReceiverPlaneFromNeighbours: the gradient vs the inverse of the steps' matrix in double (" + n + " queries, " +
          std::to_string(singular) + " singular, " + std::to_string(clamped) + " clamped; " + std::to_string(left_out) +
          " left out: |det| within rounding of the parallel-steps bound; query k at (k, 0)[x, y])",
      gradients);
  add("pnReceiverPlaneRange: the plane's (min, max) over 1..48-texel rectangles vs every texel centre (" + n +
          " queries, query k at (k, 0)[min, max])",
      ranges);
  add("pnReceiverPlaneThreshold: the receiver's depth down its plane at the rectangle's last texel, capped at the "
      "depth, vs the definition in double (" + n + " queries, query k at (k, 0))",
      thresholds);
  add("pnReceiverPlaneThresholdRange: the texels' thresholds' (min, max) over the rectangle, capped at the depth, "
      "vs the definition in double, within the module's widening (" + n + " queries, query k at (k, 0)[min, max])",
      threshold_ranges);
  return results;
}

}  // namespace pn
