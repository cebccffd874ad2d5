// One pass compiled once per set of #defines it is asked for: a pass whose
// switches are compile-time constants in each program, so a driver that runs
// every side of a branch it cannot prove uniform (llvmpipe) runs only the
// taken one. Programs are compiled on first use and kept.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gl/compute_program.h"
#include "shader/source_tree.h"

namespace pn {

class PassVariants {
 public:
  PassVariants(const Context& context, const SourceTree& tree, std::string pass);

  // The program of `defines` (compiled now if it is the first request; throws Error as compile_pass).
  const ComputeProgram& get(const std::vector<Define>& defines) const;

 private:
  const Context* context_;
  SourceTree tree_;
  std::string pass_;
  mutable std::map<std::string, std::unique_ptr<ComputeProgram>> programs_;  // by "NAME=value;…"
};

}  // namespace pn
