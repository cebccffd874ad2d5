// Helpers of the GL tests: run a module check on a glsl root, and make a copy
// of glsl/ with one deliberate mistake that the check must catch.
#pragma once

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>
#include <unistd.h>

#include "check/module_check.h"
#include "gl_test_context.h"

namespace pn::test {

// `quick`: the check's --quick (every program, fewer fixtures and no large-data case), for the
// broken copies whose mistake shows on those (the suite's 8 minutes).
inline constexpr bool kQuick = true;  // run_check's `quick`

inline std::vector<CaseResult> run_check(const ModuleCheck& check, const std::filesystem::path& root,
                                         bool quick = false) {
  const SourceTree tree(root);
  CheckOptions options;
  options.quick = quick;
  return check.run({gl_context(), tree, options});
}

// Every case passes; a failing one is reported with its where / expected / observed.
inline void check_all_pass(const std::vector<CaseResult>& results) {
  for (const auto& r : results) {
    INFO(r.name << ": " << r.comparison.where(r.tolerance));
    CHECK(r.comparison.pass);
  }
}

// Failing cases, each required to say where / expected / observed.
inline size_t failing_cases(const std::vector<CaseResult>& results) {
  size_t n = 0;
  for (const auto& r : results) {
    if (r.comparison.pass) continue;
    ++n;
    CHECK(r.comparison.where(r.tolerance).find("expected") != std::string::npos);
  }
  return n;
}

// Whether a case's name contains `part`.
inline bool named(const CaseResult& r, const char* part) { return r.name.find(part) != std::string::npos; }

// Failing cases whose name contains `part`.
inline size_t failing_named(const std::vector<CaseResult>& results, const char* part) {
  size_t n = 0;
  for (const auto& r : results)
    if (!r.comparison.pass && named(r, part)) ++n;
  return n;
}

// A copy of glsl/ with the first `from` in `file` replaced by `to` (for each
// pair); removed on destruction.
class BrokenCopy {
 public:
  using Edit = std::pair<std::string, std::string>;
  BrokenCopy(const std::string& file, const std::string& from, const std::string& to)
      : BrokenCopy(file, std::vector<Edit>{{from, to}}) {}
  BrokenCopy(const std::string& file, const std::vector<Edit>& edits)
      : root_(std::filesystem::temp_directory_path() / ("penumbra-broken-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(root_);
    std::filesystem::copy(PENUMBRA_GLSL_DIR, root_, std::filesystem::copy_options::recursive);
    std::ifstream in(root_ / file);
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    found_ = true;
    for (const auto& [from, to] : edits) {
      const size_t at = s.find(from);
      found_ = found_ && at != std::string::npos;
      if (at != std::string::npos) s.replace(at, from.size(), to);
    }
    std::ofstream(root_ / file) << s;
  }
  ~BrokenCopy() { std::filesystem::remove_all(root_); }
  BrokenCopy(const BrokenCopy&) = delete;
  BrokenCopy& operator=(const BrokenCopy&) = delete;
  const std::filesystem::path& root() const { return root_; }
  bool found() const { return found_; }

 private:
  std::filesystem::path root_;
  bool found_ = false;
};

}  // namespace pn::test
