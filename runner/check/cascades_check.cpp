// Cases of the cascades check: glsl/cascades.h and cascades.glsl through
// passes/cascades_query.comp against reference/cascades_reference (the
// definitions in double), and the runner's cascade fit (cascades/cascade_fit,
// the same formulas in float) for the properties a stable cascade promises.
//
// Tolerances, u = 2^-24:
// - splits: GLSL's pow is exp2(t log2(f/n)) with log2 within 3 ulp and exp2
//   within 3 + 2|x| ulp (GLSL 4.50 §4.7.1); for f/n <= 10^4 (|x| <= 13.3)
//   that is < 60 ulp of the power, plus a few roundings of Eq. 7's two
//   positive terms (no cancellation): relative 128 u. The hybrid split is a
//   minimum of such values times factors (a few more roundings): the same
//   bound. The endpoints C_0 = n and C_m = f are exact.
// - adaptive lambda: 0.4 · 0.301 · log2(f/n)'s error (3 ulp of <= 14): absolute 2^-18.
// - enlargement: (k - 1) / 2^(i - 1) + 1, two roundings: relative 4 u.
// - selection: index and next exact (the same float splits on both sides);
//   the weight's error is the band start's rounding over the band's width
//   plus the division's: absolute 4 u f / (narrowest band) + 8 u, printed per case.
//   Continuity across each split (band > 0): the blended visibility just
//   below a split and at it differ by < 1e-4.
// - slice sphere: centre and radius relative 32 u against a ternary search over
//   the on-axis centre (300 steps, converged far below float rounding); every
//   corner within the GPU's radius (1 + 32 u).
// - snap: floor(x / t + 0.5) exact, leaving out queries within 8 u (|x / t| + 1)
//   of a rounding boundary (GLSL's division is within 2.5 ulp); the number left
//   out is printed and must stay below 1 %.
// - stability (CPU, the runner's fit): along a camera path of sub-texel moves
//   and small turns, a world point's map position changes by whole texels
//   within 0.01 texel (float matrices), and the radius not at all; the unstable
//   fit must show a fractional change of at least 0.05 texel (the measure can
//   tell them apart). Every corner of each cascade's fitted slice lies inside
//   its map (within 0.001 texel) and before its depth range's far end, for both fits.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "cascades/cascade_fit.h"
#include "cascades/cascade_math.h"
#include "check/module_check.h"
#include "core/format.h"
#include "core/query_grid.h"
#include "gl/compute_program.h"
#include "gl/pass_bindings.h"
#include "gl/std140.h"
#include "gl/texture.h"
#include "cascades/cascaded_frame.h"
#include "passes/cascade_blend_pass.h"
#include "passes/shadow_map_pass.h"
#include "scene/city_scene.h"
#include "technique/cascaded_technique.h"
#include "frame/scene_frame.h"
#include "technique/shadow_map_sources.h"
#include "technique/technique_registry.h"
#include "truth/ray_traced_truth.h"
#include "reference/cascades_reference.h"

namespace pn::glsl {
#include "passes/cascades_query.h"
PN_STD140_SIZE(PnCascadesQueryParams, 48);
PN_STD140_OFFSET(PnCascadesQueryParams, kind, 16);
PN_STD140_OFFSET(PnCascadesQueryParams, enlargement, 36);
}  // namespace pn::glsl

namespace pn {
namespace {

constexpr double kUlp = 1.0 / (1 << 24);

// A list of values as a one-row image, for compare().
Image row_image(const std::vector<float>& values) {
  Image image(std::max<int>(1, static_cast<int>(values.size())), 1, 1);
  for (size_t k = 0; k < values.size(); ++k) image.at(static_cast<int>(k), 0, 0) = values[k];
  return image;
}

CaseResult row_case(const std::string& name, const std::vector<float>& expected, const std::vector<float>& observed,
                    const Tolerance& tolerance) {
  return {name, tolerance, compare(row_image(expected), row_image(observed), tolerance)};
}

struct QueryRun {
  const CheckEnvironment& env;
  const ComputeProgram& program;

  std::vector<Query> run(const glsl::PnCascadesQueryParams& block, const std::vector<Query>& queries) const {
    const Image input = query_image(queries);
    const GlObject query_texture = upload_float_texture(env.context, input);
    const GlObject result = make_float_texture(env.context, input.width, input.height, 4);
    {
      PassBindings bind(env.context);
      bind.uniform(block);
      bind.texture(PN_CASCADES_QUERY_QUERIES_BINDING, query_texture);
      bind.image(PN_CASCADES_QUERY_RESULTS_BINDING, result, GL_WRITE_ONLY, GL_RGBA32F);
      program.dispatch(input.width, input.height);
    }
    const Image observed = read_float_texture(env.context, result, input.width, input.height, 4);
    std::vector<Query> out;
    for (size_t k = 0; k < queries.size(); ++k) out.push_back(query_result(observed, k));
    return out;
  }
};

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

void split_cases(const QueryRun& gpu, std::vector<CaseResult>& results) {
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
      const std::vector<Query> out = gpu.run(block, queries);
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
  const Tolerance split_tolerance = Tolerance::relative(128 * kUlp);
  results.push_back(row_case("practical split C_i (Eq. 7) vs the formula in double, lambda 0...1, f/n 6.7...5000, m 1-4",
                             practical_expected, practical_gpu, split_tolerance));
  results.push_back(row_case("hybrid split C'_i (k 1...100, gap 0.001...0.9) vs the closed-form minimum in double",
                             hybrid_expected, hybrid_gpu, split_tolerance));
  results.push_back(row_case("ordering: n = C'_0 < C'_1 < ... < C'_m = f for every k, gap, lambda (1 = held)",
                             std::vector<float>(ordered.size(), 1.0f), ordered, Tolerance::exact()));
  results.push_back(row_case("adaptive lambda = 0.6 + 0.4 clamp(log10(f/n) - 2, 0, 1)", lambda_expected, lambda_gpu,
                             Tolerance::absolute(1.0 / (1 << 18))));
  results.push_back(row_case("enlargement k_i = 1 + (k - 1) / 2^(i - 1)", k_expected, k_gpu,
                             Tolerance::relative(4 * kUlp)));
  results.push_back(row_case("the runner's splits (cascade_math.h in float) vs the formulas in double",
                             [&] { auto v = practical_expected; v.insert(v.end(), hybrid_expected.begin(), hybrid_expected.end()); return v; }(),
                             [&] { auto v = practical_cpu; v.insert(v.end(), hybrid_cpu.begin(), hybrid_cpu.end()); return v; }(),
                             split_tolerance));
  results.push_back(row_case("the runner's splits are ordered too (1 = held)", std::vector<float>(ordered_cpu.size(), 1.0f),
                             ordered_cpu, Tolerance::exact()));
}

// --- selection and blending -------------------------------------------------------------------------------

void selection_cases(const QueryRun& gpu, std::vector<CaseResult>& results) {
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
          const std::vector<Query> out = gpu.run(block, queries);
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
          const double weight_bound = 4 * kUlp * far / (band > 0 ? narrowest : 1.0) + 8 * kUlp;
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

void sphere_cases(const QueryRun& gpu, std::vector<CaseResult>& results) {
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
  const std::vector<Query> out = gpu.run(params(PN_CASCADES_QUERY_SPHERE), queries);
  std::vector<float> expected, observed, inside;
  for (size_t q = 0; q < slices.size(); ++q) {
    const Slice& s = slices[q];
    const double tan_diagonal = queries[q][2];  // the float the shader saw, split back into x and y in proportion
    const double scale = tan_diagonal / std::sqrt(s.tan_x * s.tan_x + s.tan_y * s.tan_y);
    const SphereReference ref = slice_sphere_reference(queries[q][0], queries[q][1], s.tan_x * scale, s.tan_y * scale);
    expected.insert(expected.end(), {static_cast<float>(ref.centre), static_cast<float>(ref.radius)});
    observed.insert(observed.end(), {out[q][0], out[q][1]});
    const double farthest = farthest_corner_distance(queries[q][0], queries[q][1], s.tan_x * scale, s.tan_y * scale, out[q][0]);
    inside.push_back(farthest <= out[q][1] * (1 + 32 * kUlp) ? 1.0f : 0.0f);
  }
  results.push_back(row_case("slice sphere (centre, radius) vs the smallest on-axis sphere around the 8 corners",
                             expected, observed, Tolerance::relative(32 * kUlp)));
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
        near_boundary |= std::fabs(scaled - std::round(scaled)) < 8 * kUlp * (std::fabs(scaled) + 1);
        snapped[static_cast<size_t>(c)] = static_cast<float>(std::floor(scaled));
      }
      if (near_boundary) {
        ++left_out;
        continue;
      }
      snap_queries.push_back({x, y, t, 0});
      snap_expected.insert(snap_expected.end(), snapped.begin(), snapped.end());
    }
  const std::vector<Query> snapped = gpu.run(params(PN_CASCADES_QUERY_SNAP), snap_queries);
  std::vector<float> snap_observed;
  for (const Query& r : snapped) snap_observed.insert(snap_observed.end(), {r[0], r[1]});
  results.push_back(row_case("snap: floor(x / texel + 0.5) in whole texels (exact; " + std::to_string(left_out) + " of " +
                                 std::to_string(tried) + " queries within rounding of a boundary left out)",
                             snap_expected, snap_observed, Tolerance::exact()));
  results.push_back(row_case("snap: queries left out below 1 %", {0.0f},
                             {left_out * 100 < tried ? 0.0f : static_cast<float>(left_out)}, Tolerance::exact()));
}

// --- the blend pass: a technique's cascades into one visibility -------------------------------------------

// cascade_blend.comp over a screen of view depths (split ends, one ulp either side, band starts,
// uniform samples, pixels without a surface) and per-cascade visibilities of seeded noise,
// against the selection and blend in double. The weight's bound as in the selection cases.
void blend_pass_cases(const CheckEnvironment& env, std::vector<CaseResult>& results) {
  const CascadeBlendPass pass(env.context, env.tree);
  const float near = 0.5f, far = 400.0f;
  const int size = 64;
  for (int count = 1; count <= PN_CASCADES_MAX; ++count) {
    CascadeSettings settings;
    settings.count = count;
    const std::vector<float> split_far = cascade_split_far(settings, near, far);
    std::mt19937 random(0xb1e0u + static_cast<unsigned>(count));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<float> depths;
    for (int i = 0; i < count; ++i) {
      const float end = split_far[static_cast<size_t>(i)], start = i == 0 ? near : split_far[static_cast<size_t>(i - 1)];
      const float band_start = static_cast<float>(end - settings.band * (static_cast<double>(end) - start));
      for (float z : {std::nextafter(end, 0.0f), end, std::nextafter(end, INFINITY), band_start, 0.5f * (band_start + end)})
        depths.push_back(z);
    }
    Image view_depth(size, size, 4, 0.0f);
    std::vector<Image> visibility(static_cast<size_t>(count), Image(size, size, 1));
    for (int k = 0; k < size * size; ++k) {
      const int x = k % size, y = k / size;
      const float z = k < static_cast<int>(depths.size()) ? depths[static_cast<size_t>(k)]
                                                          : static_cast<float>(0.4 * std::pow(1100.0, unit(random)));
      view_depth.at(x, y, 2) = z;
      view_depth.at(x, y, 3) = k % 17 == 5 ? 0.0f : 1.0f;  // some pixels see no surface
      for (Image& v : visibility) v.at(x, y) = static_cast<float>(unit(random));
    }
    const GlObject view_texture = upload_float_texture(env.context, view_depth);
    std::vector<GlObject> textures;
    std::vector<const GlObject*> pointers;
    for (const Image& v : visibility) textures.push_back(upload_float_texture(env.context, v));
    for (const GlObject& t : textures) pointers.push_back(&t);
    CascadeInputs inputs;
    inputs.layers.resize(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) inputs.split_far[i] = split_far[static_cast<size_t>(i)];
    inputs.view_depth = &view_texture, inputs.near = near, inputs.band = static_cast<float>(settings.band);
    inputs.fade_last = count % 2 == 0;
    const Image observed = read_float_texture(env.context, pass.run(inputs, pointers, size), size, size, 1);
    Image expected(size, size, 1);
    double narrowest = INFINITY;
    std::vector<double> split_far_d(split_far.begin(), split_far.end());
    for (int i = 0; i < count; ++i)
      narrowest = std::min(narrowest, settings.band * (split_far_d[static_cast<size_t>(i)] - (i == 0 ? near : split_far_d[static_cast<size_t>(i - 1)])));
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        if (view_depth.at(x, y, 3) == 0.0f) {
          expected.at(x, y) = 1.0f;
          continue;
        }
        const CascadeChoiceReference c = cascade_choice_reference(view_depth.at(x, y, 2), near, split_far_d, settings.band, inputs.fade_last);
        const auto value = [&](int cascade) { return cascade < count ? static_cast<double>(visibility[static_cast<size_t>(cascade)].at(x, y)) : 1.0; };
        expected.at(x, y) = static_cast<float>((1 - c.weight) * value(c.index) + c.weight * value(c.next));
      }
    const Tolerance tolerance = Tolerance::absolute(4 * kUlp * far / narrowest + 16 * kUlp);
    results.push_back({"blend pass, m " + std::to_string(count) + (inputs.fade_last ? ", last fades" : "") +
                           ": each pixel's visibility from its cascade and the next vs the definition",
                       tolerance, compare(expected, observed, tolerance)});
  }
}

// --- the cascaded hard shadow on the city against the ray-traced truth -----------------------------------

// The share of light-facing pixels whose hard shadow (pcf, 2×2) differs from the truth's by more
// than half: the aliasing error of one map configuration.
double hard_shadow_mismatch(const Image& visibility, const Truth& truth) {
  long facing = 0, wrong = 0;
  for (int y = 0; y < visibility.height; ++y)
    for (int x = 0; x < visibility.width; ++x) {
      if (truth.faces_light.at(x, y) == 0.0f) continue;
      ++facing;
      wrong += std::fabs(visibility.at(x, y) - truth.visibility.at(x, y)) > 0.5f ? 1 : 0;
    }
  return facing > 0 ? static_cast<double>(wrong) / static_cast<double>(facing) : 0.0;
}

// What the city's cases share: the scene (its models read once) at 512² maps, and the passes
// that draw and blend its cascades.
struct CityRig {
  static constexpr int kMap = 512;
  explicit CityRig(const CheckEnvironment& env)
      : city(make_city_scene(fixtures::kCityScenes[0], kMap)),
        resources(env.context, env.tree),
        gbuffer(env.context, env.tree),
        maps(env.context, env.tree),
        blend(env.context, env.tree) {}
  const Scene city;
  TechniqueResources resources;
  const GBufferRenderer gbuffer;
  const ShadowMapRenderer maps;
  const CascadeBlendPass blend;
};

// The city under a point-like sun (1e-5 rad: penumbrae of 1e-5 of the blocker distance), 128²
// screen, 512² maps: the hard shadow of one map over the whole scene and of 1 to 4 cascades
// against the ray-traced truth (one sample a pixel). Cascades must alias less than the whole-
// scene map from two on (a single stable cascade is the whole frustum's sphere, wider than the
// scene's own box: measured 0.098 against 0.048), and 3 cascades less than 1.
void city_hard_shadow_cases(const CheckEnvironment& env, CityRig& rig, std::vector<CaseResult>& results) {
  constexpr int kScreen = 128, kMap = CityRig::kMap;
  Scene city = rig.city;
  light_by_sun(city, city.sun->direction, 1e-5);
  TruthSettings truth_settings;
  truth_settings.samples_per_side = 1;
  truth_settings.progress = false;
  const Truth truth = trace_truth(city, kScreen, truth_settings);
  const auto pcf = parse_technique("pcf")->create(rig.resources);
  const GBufferRenderer& gbuffer = rig.gbuffer;
  const auto full = find_shadow_map_source("full").make(env.context, env.tree, {});
  const SceneFrame whole = render_scene_frame(env.context, *full, gbuffer, city, kScreen);
  const double whole_error = hard_shadow_mismatch(
      read_float_texture(env.context, pcf->run(whole.inputs(), false).visibility, kScreen, kScreen, 1), truth);
  std::vector<double> errors;
  for (int count = 1; count <= PN_CASCADES_MAX; ++count) {
    CascadeSettings settings;
    settings.count = count, settings.map_size = kMap;
    const auto frame = render_cascaded_frame(env.context, rig.maps, gbuffer, city, settings, kScreen);
    const CascadedTechnique on_cascades(*pcf, rig.blend, env.context);
    errors.push_back(hard_shadow_mismatch(
        read_float_texture(env.context, on_cascades.run(frame->inputs(city.light), false).visibility, kScreen, kScreen, 1),
        truth));
  }
  std::string table = "whole-scene map " + format_number("%.4f", whole_error);
  for (size_t m = 0; m < errors.size(); ++m) table += ", m " + std::to_string(m + 1) + " " + format_number("%.4f", errors[m]);
  // Each case holds when its excess is 0 (observed = how far the claim misses).
  for (size_t m = 1; m < errors.size(); ++m)  // one stable cascade spans the frustum's sphere: coarser than the scene's box
    results.push_back(row_case("city hard shadow vs the truth, share of light-facing pixels wrong (" + table + "): m " +
                                   std::to_string(m + 1) + " below the whole-scene map",
                               {0.0f}, {static_cast<float>(std::max(0.0, errors[m] - whole_error))}, Tolerance::exact()));
  results.push_back(row_case("city hard shadow: m 3 below m 1", {0.0f}, {static_cast<float>(std::max(0.0, errors[2] - errors[0]))},
                             Tolerance::exact()));
}

// --- no seams: Fast PCSS on cascades at the split borders ---------------------------------------------

// Over pairs of vertically neighbouring pixels whose view depths straddle split i's far end (p
// before it but inside the band, q after): how much more the blended visibility steps than cascade i + 1's own
// result steps between the same two pixels, mean of max(0, |out(q) - out(p)| - |v1(q) - v1(p)|).
// A seam is the step from one cascade's estimate to the next's; the band spreads it over its
// width, without it the whole difference falls between two pixels.
struct SeamMeasure {
  double excess = 0;
  long pairs = 0;
};

SeamMeasure seam_measure(const Image& out, const std::vector<Image>& layers, const Image& view_depth,
                         const std::vector<Cascade>& cascades) {
  SeamMeasure m;
  for (int y = 0; y + 1 < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      if (view_depth.at(x, y, 3) == 0.0f || view_depth.at(x, y + 1, 3) == 0.0f) continue;
      for (size_t i = 0; i + 1 < cascades.size(); ++i) {
        const float c = cascades[i].split_far;
        const float za = view_depth.at(x, y, 2), zb = view_depth.at(x, y + 1, 2);
        // Across the split, and p inside the band (where the next cascade holds it too): a silhouette
        // in front of the band is a depth edge, not a seam.
        if ((za < c) == (zb < c) || za < cascades[i + 1].fit_near) continue;
        const Image& next = layers[i + 1];
        const double step = std::fabs(out.at(x, y + 1) - out.at(x, y));
        const double own = std::fabs(next.at(x, y + 1) - next.at(x, y));
        m.excess += std::max(0.0, step - own), ++m.pairs;
      }
    }
  if (m.pairs > 0) m.excess /= static_cast<double>(m.pairs);
  return m;
}

// The city, 192² screen, 3 cascades of 512² (fitted with the band 0.1), Fast PCSS on each; the
// layers blended with the band and, for the record, with band 0 (the same maps and layers: only
// the blend differs). With the band the borders' mean excess step must stay below 0.02 — a
// visible seam is the difference between two cascades' estimates, tenths — (measured 0.0054;
// the same without the band: on this view the cascades agree at their borders, and it is the
// blend-pass cases that prove the band continuous where they do not).
void seam_cases(const CheckEnvironment& env, CityRig& rig, std::vector<CaseResult>& results) {
  constexpr int kScreen = 192;
  const Scene& city = rig.city;
  const auto fast = parse_technique("fast")->create(rig.resources);
  const CascadeBlendPass& blend = rig.blend;
  CascadeSettings settings;
  settings.count = 3, settings.map_size = CityRig::kMap;
  const auto frame = render_cascaded_frame(env.context, rig.maps, rig.gbuffer, city, settings, kScreen);
  std::vector<TechniqueFrame> runs;
  for (const TechniqueInputs& layer : frame->layers.layers) runs.push_back(fast->run(layer, false));
  std::vector<const GlObject*> visibilities;
  std::vector<Image> layers;
  for (const TechniqueFrame& run : runs) {
    visibilities.push_back(&run.visibility);
    layers.push_back(read_float_texture(env.context, run.visibility, kScreen, kScreen, 1));
  }
  const Image view_depth = read_float_texture(env.context, frame->view_depth, kScreen, kScreen, 4);
  SeamMeasure measures[2];
  for (int b = 0; b < 2; ++b) {
    CascadeInputs inputs = frame->layers;
    inputs.band = b == 0 ? static_cast<float>(settings.band) : 0.0f;
    const Image out = read_float_texture(env.context, blend.run(inputs, visibilities, kScreen), kScreen, kScreen, 1);
    measures[b] = seam_measure(out, layers, view_depth, frame->cascades);
  }
  const std::string numbers = "band 0.1: " + format_number("%.4f", measures[0].excess) + " over " +
                              std::to_string(measures[0].pairs) + " border pairs, no band: " +
                              format_number("%.4f", measures[1].excess);
  results.push_back(row_case("no seams: Fast PCSS on 3 cascades of the city, the step across split borders beyond the next "
                             "cascade's own (" + numbers + "): with the band < 0.02",
                             {0.0f}, {static_cast<float>(std::max(0.0, measures[0].excess - 0.02))},
                             Tolerance::exact()));
  results.push_back(row_case("no seams: the city's split borders are crossed by some pixel pairs (> 50)", {0.0f},
                             {measures[0].pairs > 50 ? 0.0f : 1.0f}, Tolerance::exact()));
}

// --- the runner's fit: stability along a camera path, coverage -------------------------------------------

struct PathMeasure {
  double largest_fraction = 0;  // the largest |Δu − round(Δu)| over points, frames and cascades (texels)
  double radius_change = 0;     // the largest |r_f − r_0| (world units)
  int uncovered = 0;            // fitted-slice corners outside their cascade's map or depth range
};

PathMeasure walk_camera_path(bool stable, int count) {
  CascadeSettings settings;
  settings.count = count, settings.stable = stable, settings.map_size = 1024;
  const glm::vec3 light(-0.35f, -0.8f, -0.45f), scene_lo(-200.0f, -1.0f, -200.0f), scene_hi(200.0f, 60.0f, 200.0f);
  std::mt19937 random(0xcafe + static_cast<unsigned>(count));
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<glm::dvec3> points;
  for (int p = 0; p < 64; ++p) points.push_back({150 * unit(random), 20 + 20 * unit(random), 150 * unit(random)});
  PathMeasure measure;
  std::vector<Cascade> first;
  std::vector<std::vector<glm::dvec3>> first_positions;
  const glm::dvec3 start(10.0, 1.7, 20.0);
  for (int frame = 0; frame < 40; ++frame) {
    // Sub-texel moves of the finest cascade (its texel is ~2 cm here) and turns of up to half a degree.
    const double step = frame == 0 ? 0.0 : 0.01;
    const glm::dvec3 eye = start + step * glm::dvec3(unit(random), 0.2 * unit(random), unit(random));
    const double yaw = 0.6 + (frame == 0 ? 0.0 : 0.0087 * unit(random)), pitch = -0.15;
    const glm::dvec3 forward(std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw));
    CascadeCamera camera;
    camera.view = glm::mat4(glm::lookAt(eye, eye + forward, glm::dvec3(0, 1, 0)));
    camera.fov_y_radians = 1.0, camera.aspect = 16.0 / 9.0, camera.near_plane = 0.5, camera.far_plane = 400.0;
    const std::vector<Cascade> cascades = fit_cascades(settings, camera, light, scene_lo, scene_hi);
    for (size_t c = 0; c < cascades.size(); ++c) {
      std::vector<glm::dvec3> positions;
      for (const glm::dvec3& p : points) positions.push_back(cascades[c].map_position(p, settings.map_size));
      if (frame == 0) {
        first_positions.push_back(positions);
      } else {
        for (size_t p = 0; p < points.size(); ++p)
          for (int axis = 0; axis < 2; ++axis) {
            const double moved = positions[p][axis] - first_positions[c][p][axis];
            measure.largest_fraction = std::max(measure.largest_fraction, std::fabs(moved - std::round(moved)));
          }
        measure.radius_change = std::max(measure.radius_change, std::fabs(double(cascades[c].radius) - first[c].radius));
      }
      for (double z : {double(cascades[c].fit_near), double(cascades[c].split_far)})
        for (const glm::dvec3& corner : camera.corners_at(z)) {
          const glm::dvec3 m = cascades[c].map_position(corner, settings.map_size);
          // Within float rounding of the map's edges (the tight fit puts corners on them); the depth
          // range starts at the scene's nearest point, so only its far end is the fit's to meet.
          const double margin = 1e-3, n = settings.map_size;
          const bool inside = m.x >= -margin && m.x <= n + margin && m.y >= -margin && m.y <= n + margin &&
                              m.z <= cascades[c].depth_far * (1 + 1e-6);
          measure.uncovered += inside ? 0 : 1;
        }
    }
    if (frame == 0) first = cascades;
  }
  return measure;
}

void stability_cases(std::vector<CaseResult>& results) {
  for (int count : {1, 3, 4}) {
    const PathMeasure stable = walk_camera_path(true, count), unstable = walk_camera_path(false, count);
    const std::string name = "camera path (40 frames, moves < 1 texel, turns < 0.5 deg), m " + std::to_string(count);
    results.push_back(row_case(name + ", stable: map positions move by whole texels (largest fraction " +
                                   format_number("%.2g", stable.largest_fraction) + ")",
                               {0.0f}, {static_cast<float>(stable.largest_fraction)}, Tolerance::absolute(0.01)));
    results.push_back(row_case(name + ", stable: radius unchanged", {0.0f}, {static_cast<float>(stable.radius_change)},
                               Tolerance::exact()));
    // The contrast: the tight fit's positions slide by fractions of a texel; the case holds
    // when the measure sees at least 0.05 texel (observed = min(fraction, 0.05)).
    results.push_back(row_case(name + ", unstable fit: positions slide (largest fraction " +
                                   format_number("%.2g", unstable.largest_fraction) + " >= 0.05)",
                               {0.05f}, {static_cast<float>(std::min(unstable.largest_fraction, 0.05))},
                               Tolerance::exact()));
    results.push_back(row_case(name + ": every fitted slice's corner inside its cascade's map and before its depth range's end (both fits)",
                               {0.0f, 0.0f}, {static_cast<float>(stable.uncovered), static_cast<float>(unstable.uncovered)},
                               Tolerance::exact()));
  }
}

}  // namespace

std::vector<CaseResult> run_cascades_check(const CheckEnvironment& env) {
  const ComputeProgram program = compile_pass(env.context, env.tree, "passes/cascades_query.comp");
  const QueryRun gpu{env, program};
  std::vector<CaseResult> results;
  split_cases(gpu, results);
  selection_cases(gpu, results);
  sphere_cases(gpu, results);
  blend_pass_cases(env, results);
  CityRig rig(env);
  city_hard_shadow_cases(env, rig, results);
  seam_cases(env, rig, results);
  stability_cases(results);
  return results;
}

}  // namespace pn
