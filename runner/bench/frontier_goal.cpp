#include "bench/frontier_goal.h"

#include <algorithm>
#include <iomanip>

#include "core/error.h"
#include "core/format.h"
#include "draw/line_chart.h"
#include "technique/technique_registry.h"

namespace pn {

namespace {

std::string ratio_text(const std::optional<double>& r) { return r ? format_number("%.2f", *r) + "x" : "-"; }
std::string value_text(const std::optional<double>& v) { return v ? format_number("%.4f", *v) : "-"; }

}  // namespace

std::vector<std::string> with_unbounded_walk(std::vector<std::string> techniques) {
  const auto has = [&](const std::string& t) { return std::find(techniques.begin(), techniques.end(), t) != techniques.end(); };
  if (has(kFrontierDefault) && has(kPoissonTechnique) && !has(kFastUnbounded)) techniques.push_back(kFastUnbounded);
  return techniques;
}

void require_goal_inputs(const FrontierBenchSetup& setup) {
  if (!setup.estimate) throw Error("--goal-plot: draws the GPU estimate: expected --estimate FAMILY, not off");
  const std::vector<std::string> run = setup.techniques.empty() ? frontier_techniques() : setup.techniques;
  const auto has = [&](const char* t) { return std::find(run.begin(), run.end(), t) != run.end(); };
  if (!has(kFrontierDefault) || !has(kPoissonTechnique))
    throw Error(std::string("--goal-plot: draws ") + kFrontierDefault + " against " + kPoissonTechnique +
                ": expected both in --techniques");
}

std::vector<FrontierGoalRow> frontier_goal_rows(const std::vector<FrontierPoint>& points) {
  std::vector<FrontierGoalRow> out;
  for (const FrontierPoint& p : points) {
    const FrontierRow* fast = frontier_row(p, kFrontierDefault);
    const FrontierRow* poisson = frontier_row(p, kPoissonTechnique);
    if (!fast || !poisson) continue;
    FrontierGoalRow g;
    g.scene = p.scene, g.size = p.size, g.width = p.width;
    // The smallest width of this scene and size in the run, and fast's estimate there.
    const FrontierPoint* first = &p;
    for (const FrontierPoint& q : points)
      if (q.scene == p.scene && q.size == p.size && q.width < first->width && frontier_row(q, kFrontierDefault)) first = &q;
    g.first_width = first == &p;
    if (fast->estimate_ms && poisson->estimate_ms) g.estimate_ratio = *fast->estimate_ms / *poisson->estimate_ms;
    g.time_ratio = fast->ms / poisson->ms;
    const FrontierRow* fast_first = frontier_row(*first, kFrontierDefault);
    if (fast->estimate_ms && fast_first->estimate_ms) g.growth = *fast->estimate_ms / *fast_first->estimate_ms;
    g.fast_mae = fast->mae, g.poisson_mae = poisson->mae, g.fast_ssim = fast->ssim, g.poisson_ssim = poisson->ssim;
    if (const FrontierRow* unbounded = frontier_row(p, kFastUnbounded)) {
      g.unbounded_mae = unbounded->mae, g.unbounded_ssim = unbounded->ssim;
      if (unbounded->estimate_ms && poisson->estimate_ms)
        g.unbounded_estimate_ratio = *unbounded->estimate_ms / *poisson->estimate_ms;
    }
    out.push_back(g);
  }
  return out;
}

void print_frontier_goal(std::ostream& out, const std::vector<FrontierGoalRow>& rows) {
  if (rows.empty()) return;
  out << "fast against " << kPoissonTechnique << " (issue 52: estimate <= 1x at the smallest width, <= 2x above; "
      << "growth <= 2x; MAE <= and SSIM >= Poisson's; 'unbounded': " << kFastUnbounded << "):\n"
      << std::left << std::setw(14) << "scene" << std::right << std::setw(6) << "size" << std::setw(7) << "width"
      << std::setw(10) << "est." << std::setw(11) << "unbounded" << std::setw(9) << "time" << std::setw(9) << "growth"
      << std::setw(10) << "MAE"
      << std::setw(10) << "Poisson" << std::setw(11) << "unbounded" << std::setw(8) << "SSIM" << std::setw(9)
      << "Poisson" << std::setw(11) << "unbounded" << "  goals\n";
  int cheap = 0, flat = 0, closer = 0;
  for (const FrontierGoalRow& g : rows) {
    cheap += g.cheap_enough(), flat += g.flat_enough(), closer += g.closer();
    out << std::left << std::setw(14) << g.scene << std::right << std::setw(6) << g.size << std::setw(7)
        << ("x" + format_number("%g", g.width)) << std::setw(10) << ratio_text(g.estimate_ratio) << std::setw(11)
        << ratio_text(g.unbounded_estimate_ratio) << std::setw(9)
        << ratio_text(g.time_ratio) << std::setw(9) << ratio_text(g.growth) << std::setw(10)
        << format_number("%.4f", g.fast_mae) << std::setw(10) << format_number("%.4f", g.poisson_mae) << std::setw(11)
        << value_text(g.unbounded_mae) << std::setw(8) << format_number("%.4f", g.fast_ssim) << std::setw(9)
        << format_number("%.4f", g.poisson_ssim) << std::setw(11) << value_text(g.unbounded_ssim) << "  "
        << (g.cheap_enough() ? "cost " : "") << (g.flat_enough() ? "flat " : "") << (g.closer() ? "closer" : "") << "\n";
  }
  const size_t n = rows.size();
  out << "points meeting each goal: cost " << cheap << "/" << n << ", flat " << flat << "/" << n << ", closer "
      << closer << "/" << n << "\n";
}

nlohmann::json frontier_goal_json(const std::vector<FrontierGoalRow>& rows) {
  nlohmann::json list = nlohmann::json::array();
  const auto optional = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
  for (const FrontierGoalRow& g : rows)
    list.push_back({{"scene", g.scene},
                    {"size", g.size},
                    {"width", g.width},
                    {"estimate_ratio", optional(g.estimate_ratio)},
                    {"time_ratio", g.time_ratio},
                    {"growth", optional(g.growth)},
                    {"cost_bound", g.cost_bound()},
                    {"fast_mae", g.fast_mae},
                    {"poisson_mae", g.poisson_mae},
                    {"fast_ssim", g.fast_ssim},
                    {"poisson_ssim", g.poisson_ssim},
                    {"unbounded_estimate_ratio", optional(g.unbounded_estimate_ratio)},
                    {"unbounded_mae", optional(g.unbounded_mae)},
                    {"unbounded_ssim", optional(g.unbounded_ssim)},
                    {"cheap_enough", g.cheap_enough()},
                    {"flat_enough", g.flat_enough()},
                    {"closer", g.closer()}});
  return list;
}

std::vector<ChartPanel> frontier_goal_panels(const std::vector<FrontierPoint>& points) {
  // Per scene and size, fast's estimate as a ratio to Poisson's against the width, the unbounded
  // walk's beside it, and the goal's bound.
  std::vector<ChartPanel> panels;
  for (size_t i = 0; i < points.size(); ++i) {
    const FrontierPoint& p = points[i];
    if (std::any_of(points.begin(), points.begin() + static_cast<long>(i),
                    [&](const FrontierPoint& q) { return q.scene == p.scene && q.size == p.size; }))
      continue;  // the scene and size's panel is drawn
    ChartPanel panel;
    panel.title = p.scene + " " + std::to_string(p.size) + "²: estimate / Poisson's";
    panel.x_label = "light width factor (log)";
    panel.y_label = "estimated time / Poisson 36/64's";
    panel.log_x = true;
    ChartSeries bounded{"fast / poisson", {214, 39, 40}, false, {}};
    ChartSeries unbounded{"unbounded walk / poisson", {120, 20, 20}, true, {}};
    ChartSeries bound{"goal: 1x, wider 2x", {0, 0, 0}, true, {}};
    bound.marker = 0;
    double smallest = p.width;
    for (const FrontierPoint& q : points)
      if (q.scene == p.scene && q.size == p.size) smallest = std::min(smallest, q.width);
    for (const FrontierPoint& q : points) {
      if (q.scene != p.scene || q.size != p.size) continue;
      const FrontierRow* poisson = frontier_row(q, kPoissonTechnique);
      if (!poisson || !poisson->estimate_ms) continue;
      const auto ratio = [&](const char* technique, ChartSeries& series) {
        const FrontierRow* r = frontier_row(q, technique);
        if (r && r->estimate_ms) series.points.emplace_back(q.width, *r->estimate_ms / *poisson->estimate_ms);
      };
      ratio(kFrontierDefault, bounded);
      ratio(kFastUnbounded, unbounded);
      bound.points.emplace_back(q.width, q.width == smallest ? 1.0 : 2.0);
    }
    if (bounded.points.empty()) continue;
    for (ChartSeries* s : {&bound, &unbounded, &bounded}) std::sort(s->points.begin(), s->points.end());
    panel.series = {bound, unbounded, bounded};
    panels.push_back(panel);
  }
  return panels;
}

Canvas frontier_goal_chart(const std::vector<FrontierPoint>& points, const std::string& title) {
  const std::vector<ChartPanel> panels = frontier_goal_panels(points);
  return draw_line_charts(title, panels, std::min(static_cast<int>(panels.size()), 5));
}

}  // namespace pn
