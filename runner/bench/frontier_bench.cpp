#include "bench/frontier_bench.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <memory>

#include "bench/frontier_goal.h"
#include "bench/sweep_bench.h"
#include "core/bounds.h"
#include "core/error.h"
#include "core/format.h"
#include "core/progress.h"
#include "draw/line_chart.h"
#include "frame/fetch_proxy.h"
#include "scene/city_scene.h"
#include "scene/model.h"
#include "scene/scene.h"
#include "technique/comparison.h"
#include "technique/technique_registry.h"

namespace pn {

namespace {

constexpr const char* kFrontierModelScene = "spider";  // fixtures::kCityModels[0] on the ground

// The scene at one map size and width factor: the setup's model, or the scene `name`.
Scene frontier_scene(const FrontierBenchSetup& setup, const std::string& name, int size, double width) {
  if (!setup.model.empty()) return sweep_scene(setup.model, size, width);
  // The scenes frontier takes, named in its refusal (issue 39 C21: it used to list the area-light three).
  const std::vector<std::string> known = FrontierBenchSetup{}.scenes;
  if (std::find(known.begin(), known.end(), name) == known.end()) {
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    throw Error("unknown scene '" + name + "': expected one of " + list);
  }
  if (name == kFrontierModelScene) return sweep_scene(fixtures::kCityModels[0], size, width);
  Scene scene = find_city_scene_fixture_or_null(name) != nullptr ? make_city_scene(*find_city_scene_fixture_or_null(name), size)
                                                                 : make_scene(find_scene_fixture(name), size);
  scale_light_width(scene, width, "light width factor");
  return scene;
}

std::optional<double> stat(const NamedValues& stats, const char* name) {
  for (const auto& [key, value] : stats)
    if (key == name) return value;
  return std::nullopt;
}

bool scans_filter_region(const std::string& technique) {
  const std::string family = technique_family(technique);
  return family == "exact" || family == "hqepcss";
}

std::string width_text(double w) { return "x" + format_number("%g", w); }

}  // namespace

FrontierBenchSetup quick_frontier_setup() {
  FrontierBenchSetup s;
  s.scenes = {"boxes", "tall_blocker"};
  s.widths = {1, 4};
  s.sizes = {128, 256};
  s.repeats = 1;
  s.truth_samples = 4;
  // Back-projection's walk at ×4 was 30 of the run's 48 s at its node budget of 4096: 64 keeps
  // the family in the run (its table row, point and estimate) at a ninth of that.
  s.techniques = {"poisson", "vogel", "fast", "hqepcss", "savsm", "vsm", "pcf", "exact",
                  "backprojection:samples=64:budget=64"};
  return s;
}

void validate_frontier_setup(const FrontierBenchSetup& s) {
  require_list_length("frontier scenes", s.scenes.size());
  require_list_length("frontier light width factors", s.widths.size());
  require_list_length("frontier sizes", s.sizes.size());
  validate_width_bench_settings(s.sizes, s.repeats, s.truth_samples, s.exact_up_to);
  if (s.screen && (*s.screen < 16 || *s.screen > 4096))
    throw Error("screen " + std::to_string(*s.screen) + ": expected 16..4096");
  for (const std::string& name : s.scenes)
    for (double w : s.widths) frontier_scene(s, name, 16, w);  // the scene (its models read), the factor, the light
  for (const std::string& m : s.techniques) parse_technique(m)->validate();
}

namespace {

// The frontier of the rows by `time` (each row's time, or none), into `flag`, and what beats the
// default by it into `beats`.
template <class Time>
void mark_by(FrontierPoint& point, Time time, bool FrontierRow::*flag, std::optional<FrontierRow>& beats) {
  for (FrontierRow& r : point.rows) {
    r.*flag = time(r).has_value();
    for (const FrontierRow& o : point.rows)
      if (&o != &r && time(o) && time(r) && *time(o) <= *time(r) && o.mae <= r.mae && (*time(o) < *time(r) || o.mae < r.mae))
        r.*flag = false;
  }
  beats.reset();
  const FrontierRow* fast = frontier_row(point, kFrontierDefault);
  if (!fast || !time(*fast)) return;
  for (const FrontierRow& o : point.rows)
    if (o.family != fast->family && time(o) && o.mae <= fast->mae && *time(o) < *time(*fast) &&
        (!beats || *time(o) < *time(*beats)))
      beats = o;
}

}  // namespace

const FrontierRow* frontier_row(const FrontierPoint& point, const std::string& technique) {
  const auto it = std::find_if(point.rows.begin(), point.rows.end(), [&](const FrontierRow& r) { return r.technique == technique; });
  return it == point.rows.end() ? nullptr : &*it;
}

void mark_frontier(FrontierPoint& point) {
  mark_by(point, [](const FrontierRow& r) { return std::optional<double>(r.ms); }, &FrontierRow::on_frontier,
          point.beats_default);
  const bool estimated = std::all_of(point.rows.begin(), point.rows.end(), [](const FrontierRow& r) { return r.estimate_ms.has_value(); });
  const auto estimate = [estimated](const FrontierRow& r) { return estimated ? r.estimate_ms : std::nullopt; };
  mark_by(point, estimate, &FrontierRow::on_estimate_frontier, point.beats_default_estimate);
}

std::vector<FrontierPoint> bench_frontier(const Context& context, const SourceTree& tree, const FrontierBenchSetup& setup) {
  validate_frontier_setup(setup);
  std::vector<std::unique_ptr<TechniqueConfig>> configs;
  // With fast and poisson, the unbounded walk too: issue 52's table weighs the budget against it.
  for (const std::string& m : with_unbounded_walk(setup.techniques.empty() ? frontier_techniques() : setup.techniques))
    configs.push_back(parse_technique(m));
  std::vector<FrontierPoint> points;
  std::optional<GpuEstimator> estimator;
  if (setup.estimate) estimator.emplace(tree, *setup.estimate);
  Progress progress("bench frontier", setup.scenes.size() * setup.sizes.size() * setup.widths.size());
  for (const std::string& name : setup.scenes)
    for (int n : setup.sizes)
      for (double w : setup.widths) {
        progress.step(name + " " + std::to_string(n) + " " + width_text(w) + ": " + std::to_string(configs.size()) +
                      " configurations, the truth");
        ComparisonSetup cs;
        cs.screen_size = setup.screen.value_or(n);
        cs.repeats = setup.repeats;
        cs.truth_samples = setup.truth_samples;
        cs.census = estimator.has_value();
        if (setup.model.empty() && find_city_scene_fixture_or_null(name)) {
          CascadeSettings c;
          c.count = kFrontierCascades, c.map_size = n, c.stable = true;
          cs.cascades = c;
        }
        for (const auto& c : configs)
          if (w <= setup.exact_up_to || !scans_filter_region(c->name())) cs.techniques.push_back(c.get());
        Comparison result = compare_techniques(context, tree, frontier_scene(setup, name, n, w), cs);
        const std::vector<GpuEstimate> estimates = estimator ? estimator->estimate(result) : std::vector<GpuEstimate>{};
        FrontierPoint p;
        p.scene = name, p.size = n, p.screen = cs.screen_size, p.width = w;
        for (const TechniqueResult& r : result.results) {
          FrontierRow row;
          row.technique = r.name, row.family = technique_family(r.name);
          row.ms = r.measurement.total_ms;
          row.ssim = r.vs_truth.light_facing.ssim, row.mae = r.vs_truth.light_facing.mae;
          row.bias = r.vs_truth.bias;
          row.fetches = stat(r.measurement.frame.stats, kFetchStat);
          row.tile_max = stat(r.measurement.frame.stats, kFetchTileMaxStat);
          if (const GpuEstimate* e = estimate_of(result, estimates, r.name)) row.estimate_ms = e->ms;
          p.rows.push_back(row);
        }
        mark_frontier(p);
        points.push_back(std::move(p));
      }
  return points;
}

void print_frontier_bench(std::ostream& out, const std::vector<FrontierPoint>& points,
                          const std::optional<GpuEstimateSetup>& estimate) {
  for (const FrontierPoint& p : points) {
    std::vector<std::string> names;
    for (const FrontierRow& r : p.rows) names.push_back(r.technique);
    const int w = name_column_width(names);
    out << "scene " << p.scene << ", " << p.size << "x" << p.size << " map, " << p.screen << "² screen, light width "
        << width_text(p.width)
        << "; light-facing pixels vs the ray-traced truth, by time:\n"
        << std::left << std::setw(w) << "technique" << std::right << std::setw(10) << "GPU ms" << std::setw(8) << "SSIM"
        << std::setw(9) << "MAE" << std::setw(8) << "acne" << std::setw(8) << "leak" << std::setw(10) << "fetch/px"
        << std::setw(10) << "tile max" << (estimate ? "    est. us" : "") << "  frontier\n";
    std::vector<const FrontierRow*> sorted;
    for (const FrontierRow& r : p.rows) sorted.push_back(&r);
    std::stable_sort(sorted.begin(), sorted.end(), [](const FrontierRow* a, const FrontierRow* b) { return a->ms < b->ms; });
    for (const FrontierRow* r : sorted) {
      out << std::left << std::setw(w) << r->technique << std::right << std::fixed << std::setprecision(2) << std::setw(10)
          << r->ms << std::setprecision(4) << std::setw(8) << r->ssim << std::setw(9) << r->mae << std::setw(8)
          << r->bias.acne << std::setw(8) << r->bias.leak << std::setprecision(1);
      if (r->fetches) out << std::setw(10) << *r->fetches << std::setw(10) << *r->tile_max;
      else out << std::setw(10) << "-" << std::setw(10) << "-";
      if (estimate) {
        if (r->estimate_ms) out << std::setw(11) << 1e3 * *r->estimate_ms;
        else out << std::setw(11) << "-";
      }
      out << (r->on_frontier ? "  *" : "") << (r->on_estimate_frontier ? "  (est. *)" : "") << "\n";
    }
    out.unsetf(std::ios::floatfield);
    const FrontierRow* fast = frontier_row(p, kFrontierDefault);
    if (fast) {
      out << kFrontierDefault << " on the frontier: ";
      if (!p.beats_default) out << "yes (no other technique reaches its MAE in less time)\n";
      else
        out << "no: " << p.beats_default->technique << " reaches MAE " << format_number("%.4f", p.beats_default->mae)
            << " <= " << format_number("%.4f", fast->mae) << " in " << format_number("%.2f", p.beats_default->ms)
            << " ms, " << format_number("%.2f", fast->ms / p.beats_default->ms) << "x less time\n";
      if (estimate && fast->estimate_ms) {
        out << kFrontierDefault << " on the estimate's frontier (" << gpu_estimate_label(*estimate) << "): ";
        if (!p.beats_default_estimate) out << "yes\n";
        else
          out << "no: " << p.beats_default_estimate->technique << " reaches MAE "
              << format_number("%.4f", p.beats_default_estimate->mae) << " in an estimated "
              << format_number("%.1f", 1e3 * *p.beats_default_estimate->estimate_ms) << " us, "
              << format_number("%.2f", *fast->estimate_ms / *p.beats_default_estimate->estimate_ms) << "x less\n";
      }
    }
    out << "\n";
  }
  print_frontier_goal(out, frontier_goal_rows(points));
}

nlohmann::json frontier_bench_json(const FrontierBenchSetup& setup, const std::vector<FrontierPoint>& points) {
  nlohmann::json list = nlohmann::json::array();
  const auto row_json = [](const FrontierRow& r) {
    return nlohmann::json{{"technique", r.technique},
                          {"family", r.family},
                          {"ms", r.ms},
                          {"ssim", r.ssim},
                          {"mae", r.mae},
                          {"acne", r.bias.acne},
                          {"leak", r.bias.leak},
                          {"fetches_per_pixel", r.fetches ? nlohmann::json(*r.fetches) : nlohmann::json(nullptr)},
                          {"fetch_tile_max", r.tile_max ? nlohmann::json(*r.tile_max) : nlohmann::json(nullptr)},
                          {"on_frontier", r.on_frontier},
                          {"estimate_ms", r.estimate_ms ? nlohmann::json(*r.estimate_ms) : nlohmann::json(nullptr)},
                          {"on_estimate_frontier", r.on_estimate_frontier}};
  };
  for (const FrontierPoint& p : points) {
    nlohmann::json rows = nlohmann::json::array();
    for (const FrontierRow& r : p.rows) rows.push_back(row_json(r));
    list.push_back({{"scene", p.scene},
                    {"size", p.size},
                    {"screen", p.screen},
                    {"width", p.width},
                    {"rows", rows},
                    {"default", kFrontierDefault},
                    {"beats_default", p.beats_default ? row_json(*p.beats_default) : nlohmann::json(nullptr)},
                    {"beats_default_by_estimate",
                     p.beats_default_estimate ? row_json(*p.beats_default_estimate) : nlohmann::json(nullptr)}});
  }
  return {{"scenes", setup.scenes}, {"widths", setup.widths}, {"sizes", setup.sizes},
          {"screen", setup.screen ? nlohmann::json(*setup.screen) : nlohmann::json("map")},
          {"repeats", setup.repeats}, {"truth_samples", setup.truth_samples},
          {"exact_up_to", setup.exact_up_to},
          {"estimate", setup.estimate ? nlohmann::json(gpu_estimate_label(*setup.estimate)) : nlohmann::json(nullptr)},
          {"points", list},
          {"fast_against_poisson", frontier_goal_json(frontier_goal_rows(points))}};
}

Canvas frontier_bench_chart(const std::vector<FrontierPoint>& points, const std::string& title,
                            const std::optional<GpuEstimateSetup>& estimate) {
  const std::vector<std::pair<std::string, Rgb>> families{
      {"poisson", {31, 119, 180}}, {"vogel", {23, 190, 207}}, {"fast", {214, 39, 40}},  {"hqepcss", {148, 103, 189}},
      {"savsm", {44, 160, 44}},    {"vsm", {188, 189, 34}},   {"pcf", {127, 127, 127}}, {"exact", {140, 86, 75}},
      {"backprojection", {255, 127, 14}}};
  // A family without a colour of its own (a technique added since) still gets its series, after these.
  std::vector<std::pair<std::string, Rgb>> series_families = families;
  const Rgb spare[] = {{227, 119, 194}, {0, 0, 128}, {128, 128, 0}, {0, 128, 128}};
  for (const FrontierPoint& p : points)
    for (const FrontierRow& r : p.rows)
      if (std::none_of(series_families.begin(), series_families.end(), [&](const auto& f) { return f.first == r.family; }))
        series_families.emplace_back(r.family, spare[(series_families.size() - families.size()) % std::size(spare)]);
  std::vector<ChartPanel> panels;
  int columns = 1;
  // The panels by measured time, then (with an estimate) the same by the estimate.
  for (const bool by_estimate : {false, true}) {
    if (by_estimate && !estimate) break;
    const auto time = [by_estimate](const FrontierRow& r) { return by_estimate ? r.estimate_ms : std::optional<double>(r.ms); };
    for (const FrontierPoint& p : points) {
      ChartPanel panel;
      panel.title = p.scene + " " + std::to_string(p.size) + "², light " + width_text(p.width) + (by_estimate ? ", estimate" : "");
      panel.x_label = by_estimate ? "estimated GPU ms, " + gpu_estimate_label(*estimate) + " (log)" : "GPU ms (log)";
      panel.y_label = "MAE vs truth, light-facing";
      panel.log_x = true;
      ChartSeries frontier{"Pareto frontier", {0, 0, 0}, true, {}};
      frontier.marker = 0;  // a line under the points
      for (const FrontierRow& r : p.rows)
        if ((by_estimate ? r.on_estimate_frontier : r.on_frontier) && time(r)) frontier.points.emplace_back(*time(r), r.mae);
      std::sort(frontier.points.begin(), frontier.points.end());
      panel.series.push_back(frontier);
      for (const auto& [family, colour] : series_families) {
        ChartSeries s{family, colour, false, {}};
        s.lines = false;
        for (const FrontierRow& r : p.rows)
          if (r.family == family && time(r)) s.points.emplace_back(*time(r), r.mae);
        panel.series.push_back(s);
      }
      ChartSeries chosen{std::string(kFrontierDefault) + " (the default: large)", {214, 39, 40}, false, {}};
      chosen.lines = false;
      chosen.marker = 13;
      for (const FrontierRow& r : p.rows)
        if (r.technique == kFrontierDefault && time(r)) chosen.points.emplace_back(*time(r), r.mae);
      panel.series.push_back(chosen);
      panels.push_back(panel);
      columns = std::max(columns, static_cast<int>(std::count_if(points.begin(), points.end(), [&](const FrontierPoint& q) {
                                    return q.scene == p.scene && q.size == p.size;
                                  })));
    }
  }
  if (estimate)  // issue 52's row: fast's estimate / Poisson's against the width
    for (ChartPanel& panel : frontier_goal_panels(points)) panels.push_back(std::move(panel));
  return draw_line_charts(title, panels, columns);
}

}  // namespace pn
