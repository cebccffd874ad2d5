// A progress line on stderr for long CPU jobs ("truth: 512x512, 256 light
// samples: 40%"), rewritten in place with \r. Silent for a job that ends
// within its first second (tests and checks stay quiet); a line once shown
// ends with a newline when the job is done.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>
#include <utility>

namespace pn {

class ProgressLine {
 public:
  explicit ProgressLine(std::string label, bool enabled = true)
      : label_(std::move(label)), enabled_(enabled), start_(std::chrono::steady_clock::now()) {}
  ~ProgressLine() { finish(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // `fraction` in [0, 1]; prints only after the first second, and only when the percentage changes.
  void update(double fraction) {
    if (!enabled_ || std::chrono::steady_clock::now() - start_ < std::chrono::seconds(1)) return;
    const int percent = static_cast<int>(fraction * 100.0);
    if (percent == shown_) return;
    shown_ = percent;
    std::fprintf(stderr, "\r%s: %d%%", label_.c_str(), percent);
    std::fflush(stderr);
  }

  // Ends a shown line with a newline (call update(1) first for a job that completed); idempotent.
  void finish() {
    if (shown_ < 0) return;
    std::fprintf(stderr, "\n");
    std::fflush(stderr);
    shown_ = -1;
  }

 private:
  std::string label_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  int shown_ = -1;  // the percentage on screen; -1: nothing shown (or finished)
};

}  // namespace pn
