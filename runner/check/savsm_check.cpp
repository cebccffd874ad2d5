// Cases of the savsm check: glsl/savsm.glsl through passes/savsm_query.comp
// (the fixed-point moments table of summed_area.glsl, the min/max mip chain)
// against savsm_reference: the same estimate in double from brute-force
// moments (two-pass mean and variance of every rectangle's texels, never a
// table) over the same rectangles.
// Maps: a ground plane sloping from depth 30 to 45 under 14 boxes at depths
// 10..25 and an empty (+Inf) corner, at 64², 256² and 1024²; lights of
// width 0.3, 2 and 8 (near 1, far 60, fov 1 rad), so the filter squares
// run from one texel to the whole map; receivers on the ground, on box tops,
// and special ones (NaN depth, off the map, before the near plane, +Inf, past
// the far plane). Settings: the default (min blocker, bound, a = 0.2), the
// table blocker, the bound off, no bleeding reduction, and a filter scale 2.
// Per receiver (u = 2^-24; R = far - near; D = 2^-B the table's step; sigma
// the rectangle's standard deviation in depth units):
//   search square  pcss_square(u, v, search width) EXACT; a receiver whose
//                  rounding lies within 1e-3 texel of flipping takes the
//                  module's square (counted);
//   moments        F's mean within R (D/2 + 16u) + 2u|mu| and variance within
//                  R² (2 s e + e² + 4u (s² + D²)) + 8u sigma², e = D/2 + 3u,
//                  s = sigma / R: the table's quantisation (each texel's x within
//                  e, so the variance within 2 s e + e²) and its float steps
//                  (summed_area.md); the sums themselves are exact;
//   blocker        min mode: the min over the mip nodes covering S, EXACT;
//                  table mode: the range of mu - v / (t - mu) over the moments'
//                  error box (5×5 points) plus 8u (|mu| + |z|); a receiver whose
//                  box straddles the "no blocker" threshold is left out (counted);
//   filter side    c · penumbra over the blocker's range (decreasing in z),
//                  plus 64u relative (the light model's float steps);
//   filter square  pcss_square(u, v, the module's side) EXACT (ties within
//                  1e-4 texel left out, counted);
//   visibility     Chebyshev over the error box of F's moments (monotone in
//                  mu and the variance), linstep, the bound's decision (exact,
//                  from a scan of the covering nodes) plus 32u;
//   fetches        the path's count (4 a table rectangle, one a covering mip
//                  node) EXACT, and at most 26 in every filter-side class.
// Chebyshev's one-sidedness: with no reduction and no bound, the visibility is
// at least the exact PCF visibility over the same filter square, less what the
// moments' error box allows and 32u — for receivers before the far plane (the
// table reads an empty texel as the far plane: behind it, empty texels occlude).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <tuple>

#include "check/module_check.h"
#include "gl/std140.h"
#include "pass_runners/export_pass.h"
#include "scene/light_block.h"
#include "core/format.h"
#include "core/integer_hash.h"
#include "core/query_grid.h"
#include "pass_runners/minmax_mip_pass.h"
#include "pass_runners/savsm_pass.h"
#include "pass_runners/summed_area_pass.h"
#include "reference/pcss_regions_reference.h"
#include "reference/savsm_reference.h"

namespace pn::glsl {
#include "exports/savsm_export.h"
PN_STD140_OFFSET(PnSavsmExport, unitScale, 52);
}  // namespace pn::glsl

namespace pn {
namespace {

constexpr double kU = 0x1p-24;
constexpr double kNear = 1.0, kFar = 60.0;
constexpr int kGridWidth = 1024;  // query_image's layout: query k at (k mod 1024, k / 1024)
constexpr int kMaxFetches = 2 * (kSavsmRectFetches + kSavsmMaxSquareFetches);

struct MapCase {
  int size;
  int receivers;
};
constexpr MapCase kMaps[] = {{64, 600}, {256, 500}, {1024, 160}};
constexpr double kLightWidths[] = {0.3, 2.0, 8.0};

double uniform(std::uint32_t seed, std::uint32_t i) { return integer_hash(seed * 0x9e3779b9u + i) / 4294967296.0; }

double ground_depth(double u, double v, int n) { return 30.0 + 12.0 * v / n + 3.0 * u / n; }

// The ground, 14 boxes and an empty corner, n×n texels of linear light depth.
Image savsm_map(int n) {
  Image map(n, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) map.at(x, y) = static_cast<float>(ground_depth(x + 0.5, y + 0.5, n));
  for (std::uint32_t b = 0; b < 14; ++b) {
    const int w = std::max(1, static_cast<int>(n * (0.04 + 0.14 * uniform(1, 4 * b)))),
              h = std::max(1, static_cast<int>(n * (0.04 + 0.14 * uniform(1, 4 * b + 1))));
    const int x0 = static_cast<int>((n - w) * uniform(1, 4 * b + 2)), y0 = static_cast<int>((n - h) * uniform(1, 4 * b + 3));
    const float depth = static_cast<float>(10.0 + 15.0 * uniform(2, b));
    for (int y = y0; y < y0 + h; ++y)
      for (int x = x0; x < x0 + w; ++x) map.at(x, y) = std::min(map.at(x, y), depth);
  }
  for (int y = 0; y < n / 8; ++y)
    for (int x = 0; x < n / 8; ++x) map.at(x, y) = std::numeric_limits<float>::infinity();
  return map;
}

std::vector<SavsmReceiver> receivers(const Image& map, int count) {
  const int n = map.width;
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  std::vector<SavsmReceiver> out;
  for (int k = 0; k < count; ++k) {
    const double u = n * uniform(3, 2 * k), v = n * uniform(3, 2 * k + 1);
    const float fu = static_cast<float>(u), fv = static_cast<float>(v);
    switch (k % 20) {
      case 0: out.push_back({fu, fv, nan}); break;
      case 1: out.push_back({-5.0f, fv, 35.0f}); break;                      // off the map
      case 2: out.push_back({fu, static_cast<float>(n + 3), 35.0f}); break;  // off the map
      case 3: out.push_back({fu, fv, 0.5f}); break;                          // before the near plane
      case 4: out.push_back({fu, fv, inf}); break;
      case 5: out.push_back({fu, fv, 80.0f}); break;  // past the far plane
      case 6: case 7: case 8: {  // on what the map holds there: a box top, or the ground
        const float d = map.at(std::min(static_cast<int>(u), n - 1), std::min(static_cast<int>(v), n - 1));
        out.push_back({fu, fv, std::isfinite(d) ? d + 0.01f : 35.0f});
        break;
      }
      default: out.push_back({fu, fv, static_cast<float>(ground_depth(u, v, n))});
    }
  }
  return out;
}

struct Config {
  const char* name;
  SavsmSettings settings;
};

std::vector<Config> configs() {
  SavsmSettings table, off, raw, wide;
  table.blocker = SavsmBlocker::table;
  raw.blocker = SavsmBlocker::table;
  off.bound = false;
  raw.bleeding_reduction = 0.0f;
  raw.bound = false;
  wide.filter_scale = 2.0f;
  wide.blocker = SavsmBlocker::table;
  return {{"default (min blocker, bound, a 0.2)", SavsmSettings{}},
          {"table blocker", table},
          {"bound off", off},
          {"table blocker, no reduction, no bound", raw},
          {"table blocker, scale 2", wide}};
}

// The fixed table's error box on a rectangle's moments (depth units), from its true spread.
struct MomentsBox {
  double mean = 0, variance = 0;
};
MomentsBox moments_box(const SavsmMoments& m) {
  const double range = kFar - kNear, step = std::ldexp(1.0, -kSummedAreaMomentBits);
  const double s = std::sqrt(std::max(m.variance, 0.0)) / range, e = 0.5 * step + 3.0 * kU;
  return {range * (0.5 * step + 16.0 * kU) + 2.0 * kU * std::fabs(m.mean),
          range * range * (2.0 * s * e + e * e + 4.0 * kU * (s * s + step * step)) + 8.0 * kU * m.variance};
}

// The blocker estimates over the error box: whether every point has a blocker, whether any
// does, and the range of z where they all do.
struct BlockerRange {
  bool all = true, any = false;
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
};
BlockerRange blocker_range(const SavsmMoments& m, const MomentsBox& box, double t, double min_variance) {
  BlockerRange r;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j) {
      const double mu = m.mean + 0.5 * i * box.mean, v = std::max(0.0, m.variance + 0.5 * j * box.variance);
      const SavsmBlockerEstimate b = savsm_blocker_from_moments(mu, v, t, min_variance, kNear);
      r.all = r.all && b.has;
      r.any = r.any || b.has;
      if (b.has) r.lo = std::min(r.lo, b.depth), r.hi = std::max(r.hi, b.depth);
    }
  const double slack = 8.0 * kU * (std::fabs(m.mean) + std::fabs(r.hi) + box.mean);
  r.lo -= slack, r.hi += slack;
  return r;
}

bool same(const Rect& a, const Rect& b) {
  return a.x == b.x && a.y == b.y && a.width == b.width && a.height == b.height;
}

// Brute-force moments of the rectangles of one map, remembered (the configurations share them).
class MomentsCache {
 public:
  explicit MomentsCache(const Image& map) : map_(&map) {}
  const SavsmMoments& operator()(const Rect& r) {
    const auto key = std::make_tuple(r.x, r.y, r.width, r.height);
    auto found = cache_.find(key);
    if (found == cache_.end()) found = cache_.emplace(key, savsm_rect_moments(*map_, r, kNear, kFar)).first;
    return found->second;
  }

 private:
  const Image* map_;
  std::map<std::tuple<int, int, int, int>, SavsmMoments> cache_;
};

struct Cases {
  BoundedElements search, blocker, side, filter, mean, variance, visibility, fetches, upper, exported;
  long search_ties = 0, filter_ties = 0, ambiguous = 0, with_filter = 0;
  int most_fetches[16] = {};  // by filter-side class floor(log2 side)
};

void rect_elements(BoundedElements& e, const Rect& expected, const Rect& observed, int x, int y) {
  const int want[4] = {expected.x, expected.y, expected.width, expected.height};
  const int got[4] = {observed.x, observed.y, observed.width, observed.height};
  for (int c = 0; c < 4; ++c) e.add(want[c], static_cast<float>(got[c]), 0.0, x, y, c);
}

void receiver_cases(const Image& map, MomentsCache& moments, const LightModel& light, const SavsmSettings& s,
                    const SavsmReceiver& r, const SavsmQueryResult& g, int k, Cases& c) {
  const int n = map.width, x = k % kGridWidth, y = k / kGridWidth;
  const float t = r.depth - s.bias;
  double margin = 1.0;
  const bool finite = std::isfinite(r.depth) && std::isfinite(r.u) && std::isfinite(r.v);
  const Rect search = finite ? pcss_square(r.u, r.v, light.search_width_texels(r.depth), n, &margin) : Rect{};
  const bool search_tie = margin < 1e-3 && !same(search, g.search);
  if (search_tie) ++c.search_ties;
  rect_elements(c.search, search_tie ? g.search : search, g.search, x, y);

  // The path in double on the module's search square; the table blocker over its error box.
  SavsmEstimate e = savsm_reference(map, light, r, s, &g.search, nullptr);
  if (e.surface && !e.lit_by_bound && s.blocker == SavsmBlocker::table) {
    const SavsmMoments& m = moments(g.search);
    const BlockerRange b = blocker_range(m, moments_box(m), t, s.min_variance);
    if (b.all != b.any) {
      ++c.ambiguous;  // the module may take either side of the threshold
      return;
    }
    c.blocker.add(b.all ? 1.0 : 0.0, g.has_blocker ? 1.0f : 0.0f, 0.0, x, y, 1);
    if (b.all && g.has_blocker) {
      c.blocker.add_interval(b.lo, b.hi, g.blocker, x, y, 0);
      const double wide = s.filter_scale * light.penumbra_texels(r.depth, b.lo);
      const double narrow = s.filter_scale * light.penumbra_texels(r.depth, b.hi);
      c.side.add_interval(narrow * (1 - 64 * kU) - 1e-6, wide * (1 + 64 * kU) + 1e-6, g.filter_side, x, y);
    }
  } else if (e.surface && !e.lit_by_bound) {  // the min blocker: exact
    c.blocker.add(e.has_blocker ? 1.0 : 0.0, g.has_blocker ? 1.0f : 0.0f, 0.0, x, y, 1);
    c.blocker.add(e.blocker, g.blocker, 0.0, x, y, 0);
    if (e.has_blocker)
      c.side.add(e.filter_side, g.filter_side, 64 * kU * e.filter_side + 1e-6, x, y);
  } else {
    c.blocker.add(0.0, g.has_blocker ? 1.0f : 0.0f, 0.0, x, y, 1);
  }

  const bool filtered = e.surface && !e.lit_by_bound && g.has_blocker;
  Rect filter{};
  if (filtered) {
    double fmargin = 1.0;
    filter = pcss_square(r.u, r.v, g.filter_side, n, &fmargin);
    if (fmargin < 1e-4 && !same(filter, g.filter)) {
      ++c.filter_ties;
      return;
    }
    rect_elements(c.filter, filter, g.filter, x, y);
  }
  // The fetches of the path the module took.
  SavsmEstimate path = e;
  path.has_blocker = filtered;
  path.filter = filter;
  const int fetches = savsm_fetches(path, s, n);
  c.fetches.add(fetches, g.fetches, 0.0, x, y);
  if (filtered) {
    int size_class = 0;
    while (size_class < 15 && (2 << size_class) <= std::max(g.filter.width, g.filter.height)) ++size_class;
    c.most_fetches[size_class] = std::max(c.most_fetches[size_class], static_cast<int>(g.fetches));
  }
  if (!filtered || filter.width == 0 || filter.height == 0) {
    c.visibility.add(1.0, g.visibility, 0.0, x, y);
    return;
  }
  ++c.with_filter;
  const SavsmMoments& f = moments(filter);
  const MomentsBox box = moments_box(f);
  c.mean.add(f.mean, g.mean, box.mean, x, y);
  c.variance.add(f.variance, g.variance, box.variance, x, y);
  const double p_lo = chebyshev_bound_variance(f.mean - box.mean, std::max(0.0, f.variance - box.variance), t, s.min_variance);
  const double p_hi = chebyshev_bound_variance(f.mean + box.mean, f.variance + box.variance, t, s.min_variance);
  const double code = s.bound ? depth_range_bound(savsm_square_range(map, filter), t) : PN_VSM_BOUND_NONE;
  const double lo = vsm_visibility(code, reduce_bleeding(p_lo, s.bleeding_reduction));
  const double hi = vsm_visibility(code, reduce_bleeding(p_hi, s.bleeding_reduction));
  c.visibility.add_interval(lo - 32 * kU, hi + 32 * kU, g.visibility, x, y);
  // Chebyshev is an upper bound of the lit share — of the table's depths, which read empty texels
  // as the far plane: for receivers before it.
  if (!s.bound && s.bleeding_reduction == 0.0f && r.depth < kFar) {
    const double slack = (p_hi - p_lo) + 32 * kU;  // the table's error may lower it by this much
    c.upper.add(0.0, static_cast<float>(std::min(0.0, g.visibility - savsm_pcf_visibility(map, filter, t) + slack)), 0.0, x, y);
  }
}

// The call as an engine makes it (exports/savsm.comp and .frag, the export `bundle --target hlsl`
// translates) on the same receivers: equal to the query pass's pnSavsm, whose visibility the
// cases above hold to the definition — the same arithmetic in another entry and stage.
void export_cases(const ExportPass& exported, const MomentsTable& table, const DeviceTexture& mip,
                  const std::vector<SavsmReceiver>& rs, const LightModel& light, const SavsmSettings& s,
                  const std::vector<SavsmQueryResult>& got, Cases& c) {
  const auto block_of = [&](const SavsmSettings& settings) {
    glsl::PnSavsmExport b{};
    set_light_fields(b, light);
    b.bias = settings.bias, b.filterScale = settings.filter_scale, b.minVariance = settings.min_variance;
    b.bleedingReduction = settings.bleeding_reduction, b.blockerMode = static_cast<int>(settings.blocker);
    b.bound = settings.bound ? 1 : 0, b.unitNear = table.range.offset, b.unitScale = table.range.scale;
    return b;
  };
  const glsl::PnSavsmExport block = block_of(s);
  std::vector<ExportReceiver> receivers;
  for (const SavsmReceiver& r : rs) receivers.push_back({r.u, r.v, r.depth, false, 0.0f, 0.0f});
  const std::vector<QueryTexture> textures{{PN_EXPORT_MOMENT_TABLE_BINDING, *table.texture}, {PN_EXPORT_MIP_BINDING, mip}};
  for (const ShadeStage stage : {ShadeStage::compute, ShadeStage::fragment}) {
    const std::vector<float> v = exported.run(stage, textures, receivers, query_block(block));
    for (std::size_t k = 0; k < rs.size(); ++k)
      c.exported.add(got[k].visibility, v[k], 0.0, static_cast<int>(k) % kGridWidth, static_cast<int>(k) / kGridWidth,
                     stage == ShadeStage::fragment ? 1 : 0);
  }
  // pnSavsmDefaults(bias) (a filter scale <= 0 asks the export for it) = savsm.h's and vsm.h's
  // values, which SavsmSettings' defaults read (layer 2).
  glsl::PnSavsmExport defaults = block;
  defaults.filterScale = 0.0f, defaults.minVariance = -1.0f, defaults.bleedingReduction = -1.0f;
  defaults.blockerMode = -1, defaults.bound = -1;
  SavsmSettings shipped;
  shipped.bias = s.bias;
  const std::vector<float> from_defaults = exported.run(ShadeStage::compute, textures, receivers, query_block(defaults));
  const std::vector<float> from_header = exported.run(ShadeStage::compute, textures, receivers, query_block(block_of(shipped)));
  for (std::size_t k = 0; k < rs.size(); ++k)
    c.exported.add(from_header[k], from_defaults[k], 0.0, static_cast<int>(k) % kGridWidth,
                   static_cast<int>(k) / kGridWidth, 2);
}

void push(std::vector<CaseResult>& results, const std::string& name, const BoundedElements& e) {
  Tolerance t;
  const Comparison c = compare_bounded(e, t);
  results.push_back({name + " (" + std::to_string(e.expected.size()) + " values)", t, c});
}

}  // namespace

std::vector<CaseResult> run_savsm_check(const CheckEnvironment& env) {
  const SummedAreaMomentsPass tables(env.device, env.tree);
  const MinMaxMipBuilder mips(env.device, env.tree);
  const SavsmQueryPass pass(env.device, env.tree);
  const ExportPass export_pass(env.device, env.tree, "savsm");
  std::vector<CaseResult> results;
  for (const MapCase& mc : kMaps) {
    if (env.options.quick && mc.size > 256) break;  // the 1024² map runs the same programs on more data
    const int n = mc.size;
    const Image map = savsm_map(n);
    const std::unique_ptr<DeviceTexture> texture = env.device.upload(map);
    const MomentsTable table = tables.build(*texture, n, n, MomentsTableKind::fixed, unit_range(kNear, kFar));
    const MinMaxMipChain mip = mips.build(*texture, n);
    const std::vector<SavsmReceiver> rs = receivers(map, mc.receivers);
    MomentsCache moments(map);
    const std::vector<Config> all_configs = configs();
    for (const Config& config : all_configs) {
      Cases c;
      for (double width : kLightWidths) {
        LightModel light;
        light.width = width;
        light.near_plane = kNear;
        light.far_plane = kFar;
        light.fov_radians = 1.0;
        light.map_size = n;
        const std::vector<SavsmQueryResult> got = pass.query(table, *mip.texture, rs, light, config.settings);
        for (size_t k = 0; k < rs.size(); ++k)
          receiver_cases(map, moments, light, config.settings, rs[k], got[k], static_cast<int>(k), c);
        if (width == kLightWidths[0] && &config == &all_configs.front())  // the call itself, once a map
          export_cases(export_pass, table, *mip.texture, rs, light, config.settings, got, c);
      }
      const std::string label = std::to_string(n) + "x" + std::to_string(n) + " " + config.name + ": ";
      push(results, label + "search square vs pcss_square (" + std::to_string(c.search_ties) + " ties)", c.search);
      push(results, label + "blocker (presence exact; depth exact for min, within the moments' error box for table; " +
                        std::to_string(c.ambiguous) + " at the threshold left out)",
           c.blocker);
      push(results, label + "filter side c * penumbra over the blocker's range", c.side);
      push(results, label + "filter square vs pcss_square of the module's side (" + std::to_string(c.filter_ties) +
                        " ties)",
           c.filter);
      push(results, label + "filter mean vs brute force (" + std::to_string(c.with_filter) + " filtered)", c.mean);
      push(results, label + "filter variance vs brute force", c.variance);
      push(results, label + "visibility over the moments' error box", c.visibility);
      if (!c.exported.expected.empty())
        push(results, label + "exports/savsm (pnSavsm as an engine calls it) in compute and fragment = the query's "
                              "pnSavsm above, bit for bit; "
                              "pnSavsmDefaults(bias) = savsm.h's defaults",
             c.exported);
      std::string classes;
      int most = 0;
      for (int i = 0; i < 16; ++i)
        if (c.most_fetches[i] > 0) {
          classes += (classes.empty() ? "" : ", ") + std::to_string(1 << i) + ":" + std::to_string(c.most_fetches[i]);
          most = std::max(most, c.most_fetches[i]);
        }
      push(results, label + "texel fetches per receiver = the path's count", c.fetches);
      BoundedElements constant;
      constant.add(0.0, static_cast<float>(std::max(0, most - kMaxFetches)), 0.0, 0, 0);
      push(results, label + "constant cost: most fetches by filter side class {" + classes + "} <= " +
                        std::to_string(kMaxFetches),
           constant);
      if (!c.upper.expected.empty())
        push(results, label + "Chebyshev upper bound: visibility >= exact PCF over the filter square (receivers before far)", c.upper);
    }
  }
  return results;
}

}  // namespace pn
