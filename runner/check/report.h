// Runs module checks and prints the table of `penumbra check`.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "check/module_check.h"
#include "device/pass_origin.h"

namespace pn {

struct ModuleReport {
  std::string module;
  std::vector<CaseResult> cases;
  std::string error;  // why the check stopped (a compile or link error, a GL error, a timeout); "" when it ran
  // Where its stages came from, where the executor may take them from a copy (`--hlsl-root`):
  // printed as one line, so a check never runs the library's export in place of a copy in silence.
  std::vector<PassOrigin> origins;

  bool pass() const;
  // The failing case with the largest error, else the case closest to its bound.
  const CaseResult* worst() const;
};

// `modules` empty means every registered check. Unknown names throw Error before anything runs.
// A check that stops on an error (its copy does not compile, the driver reports an error, a
// dispatch times out) is reported as failing with that error, and the next check still runs.
std::vector<ModuleReport> run_checks(const std::vector<std::string>& modules, const CheckEnvironment& env);

// Table: module, cases, worst error, verdict; the passing headline cases' names (measurements
// a check prints beside its verdict); a line a module whose stages could come from a copy
// (`MODULE: --hlsl-root: ran …; the library's export for …`); then, for each failing module,
// its failing cases with where / expected / observed (at most `max_failures`
// each). `every_case` lists every case, passing ones too, with its worst element.
void print_report(std::ostream& out, const std::vector<ModuleReport>& reports, size_t max_failures = 10,
                  bool every_case = false);

}  // namespace pn
