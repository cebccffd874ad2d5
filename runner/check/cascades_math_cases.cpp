// The cascades check's formula cases: splits, selection and blending, the
// slice's sphere and the snap, each through passes/cascades_query.comp against
// reference/cascades_reference (tolerances: cascades_check.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "cascades/cascade_fit.h"
#include "cascades/cascade_math.h"
#include "check/cascades_cases.h"
#include "core/format.h"
#include "gl/std140.h"
#include "reference/cascades_reference.h"

namespace pn::glsl {
#include "passes/cascades_query.h"
PN_STD140_SIZE(PnCascadesQueryParams, 48);
PN_STD140_OFFSET(PnCascadesQueryParams, kind, 16);
PN_STD140_OFFSET(PnCascadesQueryParams, enlargement, 36);
}  // namespace pn::glsl

namespace pn {

namespace {

glsl::PnCascadesQueryParams params(int kind) {
  glsl::PnCascadesQueryParams block{};
  block.kind = kind;
  return block;
}

// --- splits ---------------------------------------------------------------------------------------------

struct SplitQuery {
  double lambda, near, far;
  int i, count;
};

}  // namespace

void split_cases(const CascadesQueryPass& gpu, std::vector<CaseResult>& results) {
  std::vector<SplitQuery> list;
  for (double lambda : {0.0, 0.25, 0.5, 0.75, 1.0})
    for (const auto& [near, far] : {std::pair{0.5, 400.0}, {0.1, 1000.0}, {1.0, 100.0}, {0.5, 50.0}, {2.0, 10000.0},
                                    {0.3, 2.0}})
      for (int count = 1; count <= PN_CASCADES_MAX; ++count)
        for (int i = 0; i <= count; ++i) list.push_back({lambda, near, far, i, count});
  std::vector<Query> queries;
  for (const SplitQuery& q : list)
    queries.push_back({static_cast<float>(q.lambda), static_cast<float>(q.near), static_cast<float>(q.far),
                       static_cast<float>(q.i + 16 * q.count)});

  std::vector<float> practical_expected, practical_gpu, practical_cpu, hybrid_expected, hybrid_gpu, hybrid_cpu,
      lambda_expected, lambda_gpu, k_expected, k_gpu, ordered, ordered_cpu;
  for (double k : {1.0, 1.5, 2.0, 4.0, 8.0, 100.0})
    for (double gap : {0.001, 0.1, 0.5, 0.9}) {
      glsl::PnCascadesQueryParams block = params(PN_CASCADES_QUERY_SPLITS);
      block.enlargement = static_cast<float>(k);
      block.gap = static_cast<float>(gap);
      const std::vector<Query> out = gpu.run(query_block(block), queries);
      for (size_t q = 0; q < list.size(); ++q) {
        const SplitQuery& s = list[q];
        // The reference on the float inputs the shader sees.
        const double n = static_cast<float>(s.near), f = static_cast<float>(s.far), lambda = static_cast<float>(s.lambda);
        const auto fl = [](double v) { return static_cast<float>(v); };
        const std::vector<double> hybrid = hybrid_splits_reference(lambda, n, f, s.count, static_cast<float>(k),
                                                                   static_cast<float>(gap));
        practical_expected.push_back(fl(s.i == 0 ? n : s.i == s.count ? f
                                                           : practical_split_reference(lambda, n, f, s.i, s.count)));
        hybrid_expected.push_back(fl(s.i == 0 ? n : s.i == s.count ? f : hybrid[static_cast<size_t>(s.i)]));
        practical_gpu.push_back(out[q][0]);
        hybrid_gpu.push_back(out[q][1]);
        practical_cpu.push_back(cascade_math::pnCascadePracticalSplit(fl(lambda), fl(n), fl(f), s.i, s.count));
        hybrid_cpu.push_back(cascade_math::pnCascadeHybridSplit(fl(lambda), fl(n), fl(f), s.i, s.count, fl(k), fl(gap)));
        lambda_expected.push_back(fl(adaptive_lambda_reference(n, f)));
        lambda_gpu.push_back(out[q][2]);
        if (s.i >= 1) k_expected.push_back(fl(enlargement_reference(static_cast<float>(k), s.i))), k_gpu.push_back(out[q][3]);
        // The ordering of one split list, read when its last split arrives.
        if (s.i == s.count) {
          const auto strictly_ordered = [&](const std::vector<float>& values) {
            const size_t first = values.size() - static_cast<size_t>(s.count) - 1;
            bool ok = values[first] == fl(n) && values.back() == fl(f);
            for (size_t j = first; j + 1 < values.size(); ++j) ok = ok && values[j] < values[j + 1];
            return ok ? 1.0f : 0.0f;
          };
          ordered.push_back(strictly_ordered(hybrid_gpu));
          ordered_cpu.push_back(strictly_ordered(hybrid_cpu));
        }
      }
    }
  const Tolerance split_tolerance = Tolerance::relative(128 * kCascadeUlp);
  results.push_back(row_case("practical split C_i (Eq. 7) vs the formula in double, lambda 0...1, f/n 6.7...5000, m 1-4",
                             practical_expected, practical_gpu, split_tolerance));
  results.push_back(row_case("hybrid split C'_i (k 1...100, gap 0.001...0.9) vs the closed-form minimum in double",
                             hybrid_expected, hybrid_gpu, split_tolerance));
  results.push_back(row_case("ordering: n = C'_0 < C'_1 < ... < C'_m = f for every k, gap, lambda (1 = held)",
                             std::vector<float>(ordered.size(), 1.0f), ordered, Tolerance::exact()));
  results.push_back(row_case("adaptive lambda = 0.6 + 0.4 clamp(log10(f/n) - 2, 0, 1)", lambda_expected, lambda_gpu,
                             Tolerance::absolute(1.0 / (1 << 18))));
  results.push_back(row_case("enlargement k_i = 1 + (k - 1) / 2^(i - 1)", k_expected, k_gpu,
                             Tolerance::relative(4 * kCascadeUlp)));
  results.push_back(row_case("the runner's splits (cascade_math.h in float) vs the formulas in double",
                             [&] { auto v = practical_expected; v.insert(v.end(), hybrid_expected.begin(), hybrid_expected.end()); return v; }(),
                             [&] { auto v = practical_cpu; v.insert(v.end(), hybrid_cpu.begin(), hybrid_cpu.end()); return v; }(),
                             split_tolerance));
  results.push_back(row_case("the runner's splits are ordered too (1 = held)", std::vector<float>(ordered_cpu.size(), 1.0f),
                             ordered_cpu, Tolerance::exact()));
}

// --- selection and blending -------------------------------------------------------------------------------

void selection_cases(const CascadesQueryPass& gpu, std::vector<CaseResult>& results) {
  const float near = 0.5f, far = 400.0f, nan = std::numeric_limits<float>::quiet_NaN(),
              inf = std::numeric_limits<float>::infinity();
  for (int count = 1; count <= PN_CASCADES_MAX; ++count)
    for (double k : {1.0, 3.0})
      for (double band : {0.0, 0.1, 0.5})
        for (bool fade_last : {false, true}) {
          CascadeSettings settings;
          settings.count = count, settings.lambda = 0.9, settings.enlargement = k, settings.band = band;
          const std::vector<float> split_far = cascade_split_far(settings, near, far);
          std::vector<double> split_far_d(split_far.begin(), split_far.end());
          std::vector<float> depths{near, 0.0f, -1.0f, nan, inf, -inf, far, 2 * far, 0.25f * near};
          std::mt19937 random(0xca5cu + static_cast<unsigned>(count));
          for (int s = 0; s < 300; ++s)
            depths.push_back(static_cast<float>(0.1 * std::pow(5000.0, std::uniform_real_distribution<double>(0, 1)(random))));
          std::vector<size_t> below_split;  // indices of the depths one ulp below each split
          double narrowest = INFINITY;
          for (int i = 0; i < count; ++i) {
            const float end = split_far[static_cast<size_t>(i)], start = i == 0 ? near : split_far[static_cast<size_t>(i - 1)];
            const float band_start = static_cast<float>(end - band * (static_cast<double>(end) - start));
            if (band > 0) narrowest = std::min(narrowest, static_cast<double>(end) - band_start);
            below_split.push_back(depths.size());
            for (float z : {std::nextafter(end, 0.0f), end, std::nextafter(end, inf), std::nextafter(band_start, 0.0f),
                            band_start, std::nextafter(band_start, inf), 0.5f * (band_start + end)})
              depths.push_back(z);
          }
          glsl::PnCascadesQueryParams block = params(PN_CASCADES_QUERY_SELECT);
          glm::vec4 splits(0.0f);
          for (int i = 0; i < count; ++i) splits[i] = split_far[static_cast<size_t>(i)];
          block.splitFar = glsl::std140_vec4(splits);
          block.count = count, block.near = near, block.band = static_cast<float>(band), block.fadeLast = fade_last;
          std::vector<Query> queries;
          for (float z : depths) queries.push_back({z, 0, 0, 0});
          const std::vector<Query> out = gpu.run(query_block(block), queries);
          std::vector<float> choice_expected, choice_gpu, weight_expected, weight_gpu, blend_expected, blend_gpu;
          for (size_t q = 0; q < depths.size(); ++q) {
            const CascadeChoiceReference c = cascade_choice_reference(depths[q], near, split_far_d, band, fade_last);
            choice_expected.insert(choice_expected.end(), {static_cast<float>(c.index), static_cast<float>(c.next)});
            choice_gpu.insert(choice_gpu.end(), {out[q][0], out[q][1]});
            weight_expected.push_back(static_cast<float>(c.weight));
            weight_gpu.push_back(out[q][2]);
            blend_expected.push_back(static_cast<float>((0.1 + 0.2 * c.index) * (1 - c.weight) + (0.1 + 0.2 * c.next) * c.weight));
            blend_gpu.push_back(out[q][3]);
          }
          const std::string name = "selection, m " + std::to_string(count) + ", k " + format_number("%g", k) + ", band " +
                                   format_number("%g", band) + (fade_last ? ", last fades" : "");
          const double weight_bound = 4 * kCascadeUlp * far / (band > 0 ? narrowest : 1.0) + 8 * kCascadeUlp;
          results.push_back(row_case(name + ": cascade index and next (exact)", choice_expected, choice_gpu, Tolerance::exact()));
          results.push_back(row_case(name + ": blend weight and blended visibility", [&] { auto v = weight_expected; v.insert(v.end(), blend_expected.begin(), blend_expected.end()); return v; }(),
                                     [&] { auto v = weight_gpu; v.insert(v.end(), blend_gpu.begin(), blend_gpu.end()); return v; }(),
                                     Tolerance::absolute(weight_bound)));
          if (band > 0) {
            // No seam: the blended visibility one ulp below each inner split equals the one at it.
            std::vector<float> at, below;
            for (int i = 0; i + 1 < count; ++i) {
              below.push_back(out[below_split[static_cast<size_t>(i)]][3]);
              at.push_back(out[below_split[static_cast<size_t>(i)] + 1][3]);
            }
            if (!at.empty())
              results.push_back(row_case(name + ": no seam at the splits (visibility just below == at)", at, below,
                                         Tolerance::absolute(1e-4)));
          }
        }
}

// --- the slice's sphere and the snap ------------------------------------------------------------------------

void sphere_cases(const CascadesQueryPass& gpu, std::vector<CaseResult>& results) {
  struct Slice {
    double a, b, tan_x, tan_y;
  };
  std::vector<Slice> slices;
  for (double fov_y : {0.3, 1.0, 1.5, 2.5})
    for (double aspect : {1.0, 16.0 / 9.0, 0.5})
      for (const auto& [a, b] : {std::pair{0.5, 10.0}, {10.0, 50.0}, {50.0, 400.0}, {0.5, 400.0}, {1.0, 1.01}, {100.0, 101.0}}) {
        const double ty = std::tan(0.5 * fov_y);
        slices.push_back({a, b, ty * aspect, ty});
      }
  std::vector<Query> queries;
  for (const Slice& s : slices)
    queries.push_back({static_cast<float>(s.a), static_cast<float>(s.b),
                       static_cast<float>(std::sqrt(s.tan_x * s.tan_x + s.tan_y * s.tan_y)), 0});
  const std::vector<Query> out = gpu.run(query_block(params(PN_CASCADES_QUERY_SPHERE)), queries);
  std::vector<float> expected, observed, inside;
  for (size_t q = 0; q < slices.size(); ++q) {
    const Slice& s = slices[q];
    const double tan_diagonal = queries[q][2];  // the float the shader saw, split back into x and y in proportion
    const double scale = tan_diagonal / std::sqrt(s.tan_x * s.tan_x + s.tan_y * s.tan_y);
    const SphereReference ref = slice_sphere_reference(queries[q][0], queries[q][1], s.tan_x * scale, s.tan_y * scale);
    expected.insert(expected.end(), {static_cast<float>(ref.centre), static_cast<float>(ref.radius)});
    observed.insert(observed.end(), {out[q][0], out[q][1]});
    const double farthest = farthest_corner_distance(queries[q][0], queries[q][1], s.tan_x * scale, s.tan_y * scale, out[q][0]);
    inside.push_back(farthest <= out[q][1] * (1 + 32 * kCascadeUlp) ? 1.0f : 0.0f);
  }
  results.push_back(row_case("slice sphere (centre, radius) vs the smallest on-axis sphere around the 8 corners",
                             expected, observed, Tolerance::relative(32 * kCascadeUlp)));
  results.push_back(row_case("slice sphere holds every corner (1 = held)", std::vector<float>(inside.size(), 1.0f), inside,
                             Tolerance::exact()));

  std::mt19937 random(0x5a4a);
  std::uniform_real_distribution<double> coordinate(-400.0, 400.0);
  std::vector<Query> snap_queries;
  std::vector<float> snap_expected;
  int left_out = 0, tried = 0;
  for (double texel : {0.02, 0.3, 1.7, 25.0})
    for (int s = 0; s < 400; ++s) {
      const float x = static_cast<float>(coordinate(random)), y = static_cast<float>(coordinate(random)),
                  t = static_cast<float>(texel);
      ++tried;
      bool near_boundary = false;
      std::array<float, 2> snapped{};
      for (int c = 0; c < 2; ++c) {
        const double scaled = static_cast<double>(c == 0 ? x : y) / t + 0.5;
        near_boundary |= std::fabs(scaled - std::round(scaled)) < 8 * kCascadeUlp * (std::fabs(scaled) + 1);
        snapped[static_cast<size_t>(c)] = static_cast<float>(std::floor(scaled));
      }
      if (near_boundary) {
        ++left_out;
        continue;
      }
      snap_queries.push_back({x, y, t, 0});
      snap_expected.insert(snap_expected.end(), snapped.begin(), snapped.end());
    }
  const std::vector<Query> snapped = gpu.run(query_block(params(PN_CASCADES_QUERY_SNAP)), snap_queries);
  std::vector<float> snap_observed;
  for (const Query& r : snapped) snap_observed.insert(snap_observed.end(), {r[0], r[1]});
  results.push_back(row_case("snap: floor(x / texel + 0.5) in whole texels (exact; " + std::to_string(left_out) + " of " +
                                 std::to_string(tried) + " queries within rounding of a boundary left out)",
                             snap_expected, snap_observed, Tolerance::exact()));
  results.push_back(row_case("snap: queries left out below 1 %", {0.0f},
                             {left_out * 100 < tried ? 0.0f : static_cast<float>(left_out)}, Tolerance::exact()));
}

}  // namespace pn
