// Progress of a long run, one line on standard error per step
// ("penumbra: bench sweep: [3/8] boxes 512 x4"), so that a run of minutes is
// never silent while standard output keeps only the results.
#pragma once

#include <cstddef>
#include <iostream>
#include <string>
#include <utility>

namespace pn {

class Progress {
 public:
  Progress(std::string task, size_t steps) : task_(std::move(task)), steps_(steps) {}

  // Announces the next step, before it runs.
  void step(const std::string& what) {
    ++done_;
    std::cerr << "penumbra: " << task_ << ": [" << done_ << "/" << steps_ << "] " << what << "\n";
  }

 private:
  std::string task_;
  size_t steps_;
  size_t done_ = 0;
};

}  // namespace pn
