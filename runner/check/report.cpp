#include "check/report.h"

#include <algorithm>
#include <cstdio>

#include "core/error.h"
#include "core/format.h"

namespace pn {
namespace {

// How close a case came to its bound: error / bound, with exact bounds
// counting any error as infinitely far.
double closeness(const CaseResult& c) {
  const double bound = c.tolerance.bound;
  if (bound > 0.0) return c.comparison.worst_error / bound;
  return c.comparison.worst_error > 0.0 ? 1e300 : 0.0;
}

// "MODULE: --hlsl-root: ran R/a.hlsl, …; the library's export for exports/b, passes/c (why); …":
// which copies a check ran and, grouped by reason, which entries it ran the library's export of.
std::string origins_line(const ModuleReport& r) {
  auto add = [](std::vector<std::string>& to, const std::string& what) {
    if (std::find(to.begin(), to.end(), what) == to.end()) to.push_back(what);
  };
  auto list = [](const std::vector<std::string>& names) {
    std::string out;
    for (std::size_t i = 0; i < names.size() && i < 8; ++i) out += (i ? ", " : "") + names[i];
    if (names.size() > 8) out += ", … (" + std::to_string(names.size()) + " in all)";
    return out;
  };
  std::vector<std::string> copies, reasons;
  std::vector<std::vector<std::string>> passes;                // a list a reason
  std::vector<std::vector<std::vector<std::string>>> details;  // a list a pass of a reason
  for (const PassOrigin& o : r.origins) {
    if (!o.copy.empty()) {
      add(copies, o.copy);
      continue;
    }
    add(reasons, o.why_not);
    const auto k = static_cast<std::size_t>(std::find(reasons.begin(), reasons.end(), o.why_not) - reasons.begin());
    passes.resize(reasons.size()), details.resize(reasons.size());
    const std::string name = o.pass.size() > 5 && o.pass.compare(o.pass.size() - 5, 5, ".comp") == 0
                                 ? o.pass.substr(0, o.pass.size() - 5) : o.pass;
    add(passes[k], name);
    const auto p = static_cast<std::size_t>(std::find(passes[k].begin(), passes[k].end(), name) - passes[k].begin());
    details[k].resize(passes[k].size());
    if (!o.detail.empty()) add(details[k][p], o.detail);
  }
  std::string line = r.module + ": --hlsl-root: " + (copies.empty() ? "no copy ran" : "ran " + list(copies));
  for (std::size_t k = 0; k < reasons.size(); ++k) {
    std::vector<std::string> names;
    for (std::size_t p = 0; p < passes[k].size(); ++p) {
      const std::vector<std::string>& d = details[k][p];
      names.push_back(passes[k][p] + (d.empty()       ? ""
                                      : d.size() == 1 ? " [" + d[0] + "]"
                                                      : " [" + std::to_string(d.size()) + " sets of defines]"));
    }
    line += (k ? "; and for " : "; the library's export ran for ") + list(names) + " (" + reasons[k] + ")";
  }
  return line;
}

}  // namespace

bool ModuleReport::pass() const {
  return error.empty() && !cases.empty() && std::all_of(cases.begin(), cases.end(), [](const CaseResult& c) { return c.comparison.pass; });
}

const CaseResult* ModuleReport::worst() const {
  const CaseResult* worst = nullptr;
  for (const CaseResult& c : cases) {
    const bool more_failing = worst != nullptr && !c.comparison.pass && worst->comparison.pass;
    if (worst == nullptr || more_failing ||
        (c.comparison.pass == worst->comparison.pass && closeness(c) > closeness(*worst)))
      worst = &c;
  }
  return worst;
}

std::vector<ModuleReport> run_checks(const std::vector<std::string>& modules, const CheckEnvironment& env) {
  std::vector<const ModuleCheck*> selected;
  if (modules.empty())
    for (const ModuleCheck& check : module_checks()) selected.push_back(&check);
  for (const std::string& name : modules) {
    selected.push_back(&find_module_check(name));
  }
  std::vector<ModuleReport> reports;
  for (const ModuleCheck* check : selected) {
    ModuleReport report;
    report.module = check->name;
    try {
      report.cases = check->run(env);
    } catch (const Error& e) {
      if (e.code() == ExitCode::no_context) throw;
      report.error = e.what();
    }
    reports.push_back(std::move(report));
  }
  return reports;
}

void print_report(std::ostream& out, const std::vector<ModuleReport>& reports, size_t max_failures, bool every_case) {
  char line[256];
  std::snprintf(line, sizeof line, "%-18s %6s  %-34s %s\n", "module", "cases", "worst error (tolerance)", "verdict");
  out << line;
  for (const ModuleReport& r : reports) {
    const CaseResult* w = r.worst();
    std::string worst = r.error.empty() ? "-" : "error: did not run";
    if (w != nullptr && r.error.empty()) {
      worst = format_number("%.2e", w->comparison.worst_error) + " (" + w->tolerance.describe() + ")";
    }
    std::snprintf(line, sizeof line, "%-18s %6zu  %-34s %s\n", r.module.c_str(), r.cases.size(), worst.c_str(),
                  r.pass() ? "pass" : "FAIL");
    out << line;
  }
  if (!every_case)  // every_case lists them below with the rest
    for (const ModuleReport& r : reports)
      for (const CaseResult& c : r.cases)
        if (c.headline && c.comparison.pass) out << r.module << ": " << c.name << "\n";
  for (const ModuleReport& r : reports)
    if (!r.origins.empty()) out << origins_line(r) << "\n";
  if (every_case)
    for (const ModuleReport& r : reports)
      for (const CaseResult& c : r.cases)
        out << r.module << ": " << (c.comparison.pass ? "pass " : "FAIL ") << c.name << ": "
            << c.comparison.where(c.tolerance) << "\n";
  for (const ModuleReport& r : reports) {
    if (!r.error.empty()) {
      // A driver log may hold several lines: each is printed under the module's name.
      size_t start = 0;
      for (size_t end; (end = r.error.find('\n', start)) != std::string::npos; start = end + 1)
        out << r.module << ": FAIL " << r.error.substr(start, end - start) << "\n";
      if (start < r.error.size()) out << r.module << ": FAIL " << r.error.substr(start) << "\n";
      continue;
    }
    if (r.pass() || every_case) continue;
    size_t failing = 0;
    for (const CaseResult& c : r.cases) {
      if (c.comparison.pass) continue;
      if (++failing <= max_failures)
        out << r.module << ": FAIL " << c.name << ": " << c.comparison.where(c.tolerance) << "\n";
    }
    if (failing > max_failures) out << r.module << ": ... and " << failing - max_failures << " more failing cases\n";
    if (r.cases.empty()) out << r.module << ": FAIL no cases ran\n";
  }
}

}  // namespace pn
