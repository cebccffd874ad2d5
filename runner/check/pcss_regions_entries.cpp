// What the pcss_regions check's groups of cases share (pcss_regions_cases.h):
// the entry groups and their rows, the search queries, the lit-coverage property.
#include <algorithm>
#include <array>
#include <cmath>

#include "check/pcss_regions_cases.h"
#include "check/row_image.h"
#include "pipeline/pcss_settings.h"
#include "reference/region_reference.h"

namespace pn::pcss_regions_cases {
namespace {

// The regions of an entry as the module defines them, from the entry's floats:
// pnEntryRect (4), pnEntryWindow (3), pnEntryLit (1), pnEntryLinkKey (4).
std::array<float, 12> regions_of(const std::array<float, 4>& entry, int n, RegionMode mode) {
  const RegionEntry e{entry[0], entry[1], entry[2], entry[3]};
  const Rect r = pcss_square(e.x, e.y, e.side, n, nullptr);
  const RegionWindow w = mode == RegionMode::centred ? region_centred_reference(entry[1], entry[2], entry[3], n)
                                                     : region_reference(entry[1], entry[2], entry[3], n);
  const bool lit = e.lit();
  const bool own_side = mode == RegionMode::exact || lit;
  return {float(r.x), float(r.y), float(r.width), float(r.height), float(w.u), float(w.v), float(w.side),
          lit ? 1.0f : 0.0f, entry[0], entry[1], entry[2], own_side ? entry[3] : float(w.side)};
}

// Whether float evaluation of the entry's exact square may differ from the double one:
// an exact .5 side (GLSL's round() picks either way) or an origin within 4 float ulps
// of an integer without being one.
bool square_tie(const std::array<float, 4>& entry, int n) {
  const double s = std::isnan(entry[3]) ? 0.0 : std::max(static_cast<double>(entry[3]), 0.0);
  if (!std::isfinite(s)) return false;
  if (s >= 1.5 && s - std::floor(s) == 0.5) return true;
  const double m = std::clamp(std::round(s), 1.0, 4.0 * n);
  for (float c : {entry[1], entry[2]}) {
    if (!std::isfinite(c)) continue;
    const double lo = static_cast<double>(c) - 0.5 * m + 0.5, off = std::fabs(lo - std::round(lo));
    if (off > 0.0 && off <= 4.0 * kUlp * (std::fabs(c) + m + 1.0)) return true;
  }
  return false;
}

// Whether float evaluation of an area square's cover may differ from the double one: a bound
// c ± s/2 within 4 float ulps of an integer without being one.
bool area_tie(const std::array<float, 4>& entry, int n) {
  const double s = std::clamp(std::isnan(entry[3]) ? 0.0 : std::max(static_cast<double>(entry[3]), 0.0), 1.0, 4.0 * n);
  for (float c : {entry[1], entry[2]})
    for (double bound : {c - 0.5 * s, c + 0.5 * s}) {
      const double off = std::fabs(bound - std::round(bound));
      if (std::isfinite(bound) && off > 0.0 && off <= 4.0 * kUlp * (std::fabs(c) + s + 1.0)) return true;
    }
  return false;
}

// The exact square of a tied entry, as the GPU rounded it when that is one of the
// roundings the tie allows (either side of the .5, the origin either side of the
// integer); else the double one (and the comparison fails).
Rect tied_square(const std::array<float, 4>& entry, int n, const std::array<float, 4>& observed_rect) {
  const double s = std::isnan(entry[3]) ? 0.0 : std::max(static_cast<double>(entry[3]), 0.0);
  const double x = entry[1], y = entry[2];
  const double dx = 8.0 * kUlp * (std::fabs(x) + s + 2.0), dy = 8.0 * kUlp * (std::fabs(y) + s + 2.0);
  for (double side : {s, s - 0.25, s + 0.25})
    for (double ox : {0.0, -dx, dx})
      for (double oy : {0.0, -dy, dy}) {
        const Rect r = pcss_square(x + ox, y + oy, side, n, nullptr);
        if (float(r.x) == observed_rect[0] && float(r.y) == observed_rect[1] && float(r.width) == observed_rect[2] &&
            float(r.height) == observed_rect[3])
          return r;
      }
  return pcss_square(x, y, s, n, nullptr);
}

}  // namespace

const char* mode_name(RegionMode mode) {
  switch (mode) {
    case RegionMode::window: return "window region";
    case RegionMode::exact: return "exact region";
    case RegionMode::centred: return "centred region";
  }
  return "?";
}

std::vector<int> iteration_counts() { return {0, 1, PcssSettings{}.refine_iterations, 100}; }

std::vector<NamedLight> fixture_lights(int n) {
  const auto make = [n](double width) {
    LightModel l;
    l.width = width, l.near_plane = kNear, l.far_plane = 100.0, l.fov_radians = 1.0, l.map_size = n;
    return l;
  };
  return {{"light 0.25", make(0.25)}, {"light 1", make(1.0)}, {"zero-size light", make(0.0)}};
}

void add_entry(EntryGroup& g, const RegionEntry& expected, bool ambiguous, const PcssRegionsResult& o,
               int expected_refinements) {
  ++g.queries;
  if (ambiguous) {
    ++g.left_out;
    return;
  }
  if (expected_refinements >= 0) {
    g.e_refinements.push_back(static_cast<float>(expected_refinements));
    g.o_refinements.push_back(static_cast<float>(o.refinements));
  }
  const bool o_lit = !(o.entry[3] >= 0.0f);
  g.lit += expected.lit() ? 1 : 0;
  for (float v : {expected.lit() ? 1.0f : 0.0f, float(expected.depth), float(expected.x), float(expected.y)})
    g.e_decisions.push_back(v);
  for (float v : {o_lit ? 1.0f : 0.0f, o.entry[0], o.entry[1], o.entry[2]}) g.o_decisions.push_back(v);
  const bool both = !expected.lit() && !o_lit;
  g.e_sides.push_back(both ? float(expected.side) : -1.0f);
  g.o_sides.push_back(both ? o.entry[3] : -1.0f);
}

void add_regions(EntryGroup& g, const PcssRegionsResult& o, int n, RegionMode mode, bool area_edges) {
  std::array<float, 12> expected = regions_of(o.entry, n, mode);
  if (area_edges) {
    const Rect r = area_cover(o.entry[1], o.entry[2], o.entry[3], n);
    expected[0] = float(r.x), expected[1] = float(r.y), expected[2] = float(r.width), expected[3] = float(r.height);
    if (area_tie(o.entry, n)) {
      ++g.regions_tied;
      for (int c = 0; c < 4; ++c)
        if (std::fabs(expected[static_cast<size_t>(c)] - o.rect[static_cast<size_t>(c)]) <= 1.0f)
          expected[static_cast<size_t>(c)] = o.rect[static_cast<size_t>(c)];
    }
  } else if (square_tie(o.entry, n)) {
    ++g.regions_tied;
    const Rect r = tied_square(o.entry, n, o.rect);
    expected[0] = float(r.x), expected[1] = float(r.y), expected[2] = float(r.width), expected[3] = float(r.height);
  }
  for (float v : expected) g.e_regions.push_back(v);
  for (int c = 0; c < 4; ++c) g.o_regions.push_back(o.rect[c]);
  for (int c = 0; c < 4; ++c) g.o_regions.push_back(o.window[c]);
  for (int c = 0; c < 4; ++c) g.o_regions.push_back(o.key[c]);
}

void push_group(std::vector<CaseResult>& results, const std::string& name, const EntryGroup& g, const char* what) {
  const Tolerance exact = Tolerance::exact(), side = Tolerance::relative(kSideTolerance);
  const std::string count = std::to_string(g.queries) + " " + what;
  if (!g.e_decisions.empty()) {
    const std::string left = g.left_out > 0 ? ", " + std::to_string(g.left_out) + " within rounding of a decision left out" : "";
    results.push_back({name + ": " + count + " — lit decisions (" + std::to_string(g.lit) + " lit) and (d, x, y)" + left +
                           "; kept query k at (k, 0), [0] lit",
                       exact, compare(row_image(g.e_decisions, 4), row_image(g.o_decisions, 4), exact)});
    results.push_back({name + ": " + count + " — sides of unlit entries", side,
                       compare(row_image(g.e_sides, 1), row_image(g.o_sides, 1), side)});
  }
  if (!g.e_refinements.empty())
    results.push_back({name + ": " + std::to_string(g.e_refinements.size()) +
                           " counted searches (pnSearchEntryMipCounted or …MipPlane) — refinements, the squares whose min was read",
                       exact, compare(row_image(g.e_refinements, 1), row_image(g.o_refinements, 1), exact)});
  if (!g.e_regions.empty()) {
    const std::string left = g.regions_tied > 0 ? ", " + std::to_string(g.regions_tied) +
                                                      " squares at a float tie: either rounding accepted"
                                                : "";
    results.push_back({name + ": regions of the GPU's entries" + left +
                           " — [0-3] pnEntryRect, [4-6] pnEntryWindow, [7] pnEntryLit, [8-11] pnEntryLinkKey",
                       exact, compare(row_image(g.e_regions, 12), row_image(g.o_regions, 12), exact)});
  }
}

std::vector<PcssRegionsQuery> search_queries(const std::vector<RegionReceiver>& receivers, RegionMode mode, int iterations,
                                             float bias, Structure structure) {
  std::vector<PcssRegionsQuery> out;
  for (const RegionReceiver& r : receivers) {
    PcssRegionsQuery q;
    q.kind = structure == Structure::pyramid ? PcssRegionsQuery::Kind::search
             : out.size() % 2 == 0           ? PcssRegionsQuery::Kind::search_mip
                                             : PcssRegionsQuery::Kind::search_mip_counted;
    q.mode = mode, q.input = {r.u, r.v, r.depth, r.valid};
    q.bias = bias, q.iterations = iterations;
    out.push_back(q);
  }
  return out;
}

CaseResult property_case(const std::string& name, const std::vector<float>& violations, const LitCoverage& c,
                         const std::string& extra) {
  const Image observed = row_image(violations, 1);
  return {name + ": receivers marked lit although a texel can shadow them: " + std::to_string(c.violations) + " of " +
              std::to_string(c.lit) + " lit (" + extra + std::to_string(c.left_out) +
              " within rounding left out), expected 0; checked lit receiver k at (k, 0)",
          Tolerance::exact(), compare(Image(observed.width, 1, 1, 0.0f), observed, Tolerance::exact())};
}

ShadowingTruth shadowing_truth(const DepthScan& scan, const LightModel& light, const RegionReceiver& r, double bias) {
  Rounding rounding{kAmbiguity};
  const bool shadowable = shadowing_blocker(scan, light, r, bias, &rounding);
  return {shadowable, rounding.ambiguous};
}

std::vector<ShadowingTruth> shadowing_truths(const DepthScan& scan, const LightModel& light,
                                             const std::vector<RegionReceiver>& receivers, double bias) {
  std::vector<ShadowingTruth> out;
  out.reserve(receivers.size());
  for (const RegionReceiver& r : receivers) out.push_back(shadowing_truth(scan, light, r, bias));
  return out;
}

void count_receiver(LitCoverage& c, std::vector<float>& violations, const RegionReceiver& r,
                    const PcssRegionsResult& observed, const std::function<ShadowingTruth()>& truth,
                    bool count_shadowable) {
  if (r.valid == 0.0f || std::isnan(r.depth)) return;
  ++c.receivers;
  const bool lit = !(observed.entry[3] >= 0.0f);
  if (!lit && !count_shadowable) return;
  const ShadowingTruth t = truth();
  c.shadowable += t.shadowable ? 1 : 0;
  if (!lit) return;
  ++c.lit;
  if (!t.shadowable && t.ambiguous) {
    ++c.left_out;
    return;
  }
  violations.push_back(t.shadowable ? 1.0f : 0.0f);
  c.violations += t.shadowable ? 1 : 0;
}

LitCoverage count_lit_coverage(const std::string& name, const std::vector<RegionReceiver>& receivers,
                               const std::vector<ShadowingTruth>& truths, const std::vector<PcssRegionsResult>& observed) {
  LitCoverage c;
  std::vector<float> violations;
  for (size_t k = 0; k < receivers.size(); ++k)
    count_receiver(c, violations, receivers[k], observed[k], [&] { return truths[k]; }, true);
  c.result = property_case(name, violations, c,
                           std::to_string(c.receivers) + " receivers, " + std::to_string(c.shadowable) +
                               " of them a texel can shadow; ");
  return c;
}

}  // namespace pn::pcss_regions_cases
