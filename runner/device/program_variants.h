// One pass compiled on one device once per set of #defines it is asked for: a pass whose
// switches are compile-time constants in each program, so a driver that runs every side of a
// branch it cannot prove uniform (llvmpipe) runs only the taken one. Compiled on first use, kept.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "device/query_device.h"

namespace pn {

class ProgramVariants {
 public:
  // `pass`: a compute pass under the glsl root (e.g. "passes/pcss_traverse.comp").
  ProgramVariants(const QueryDevice& device, const SourceTree& tree, std::string pass);
  // The pass compiled with `defines`. Throws Error as QueryDevice::compile_query.
  const QueryProgram& get(const std::vector<Define>& defines = {}) const;

 private:
  const QueryDevice* device_;
  SourceTree tree_;
  std::string pass_;
  mutable std::map<std::string, std::unique_ptr<QueryProgram>> made_;  // by define_key
};

}  // namespace pn
