// One pass compiled on one device per set of compile-time switches (defines), each on first use
// and kept: the executor-neutral twin of gl/pass_variants.h.
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
