// Runner side of the export entries (glsl/exports/X.comp, exports.h): the entry `bundle
// X.glsl --target hlsl|msl` translates, run as a query pass — so on `check --api hlsl` what runs
// is the module's HLSL export itself, compiled back.
#pragma once

#include <string>
#include <vector>

#include "passes/query_pass.h"

namespace pn {

struct ExportReceiver {
  float u = 0, v = 0, depth = 0;
  bool plane = false;  // through the call's receiverPlane overload, with (du, dv)
  float du = 0, dv = 0;
};

class ExportPass {
 public:
  // `module`: "pcf", "exact_pcss", "fast_pcss" (exports/<module>.comp), compiled with `defines`.
  ExportPass(const QueryDevice& device, const SourceTree& tree, const std::string& module,
             const std::vector<Define>& defines = {});
  // The call's visibility for each receiver, reading `textures` (the depth map, or the structures
  // the call reads, at the export's bindings) with the export's `block`.
  std::vector<float> run(const std::vector<QueryTexture>& textures, const std::vector<ExportReceiver>& receivers,
                         const QueryBlock& block) const;

 private:
  QueryPass query_;
};

}  // namespace pn
