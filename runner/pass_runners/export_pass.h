// Runner side of the export entries (glsl/exports/X.comp and X.frag, exports.h): the module's
// public call as `bundle X.glsl --target hlsl|msl` exports it, run over a list of receivers in a
// compute shader or in a fragment shader (a full-screen triangle) — so on `check --api hlsl` what
// runs is the module's HLSL export itself, compiled back.
#pragma once

#include <string>
#include <vector>

#include "pass_runners/shade_pass.h"

namespace pn {

struct ExportReceiver {
  float u = 0, v = 0, depth = 0;
  bool plane = false;  // through the call's receiverPlane overload, with (du, dv)
  float du = 0, dv = 0;
};

class ExportPass {
 public:
  // `module`: "pcf", "exact_pcss", "fast_pcss", … (exports/<module>.comp | .frag), compiled with `defines`.
  ExportPass(const QueryDevice& device, const SourceTree& tree, const std::string& module,
             std::vector<Define> defines = {});
  // The call's visibility for each receiver in `stage`, reading `textures` (the depth map, or the
  // structures the call reads, at the export's bindings) with the export's `block`. Receiver k sits
  // at texel (k mod s, k / s) of an s × s receiver image: the `pixel` a call takes (Fast PCSS's
  // sample set, Vogel's rotation) is that texel, in either stage.
  std::vector<float> run(ShadeStage stage, const std::vector<QueryTexture>& textures,
                         const std::vector<ExportReceiver>& receivers, const QueryBlock& block) const;

  // The side s of the receiver image for `count` receivers, and receiver k's texel.
  static int side(std::size_t count);
  static std::pair<int, int> texel(std::size_t k, std::size_t count);

 private:
  const QueryDevice* device_;
  std::vector<Define> defines_;
  ShadePass pass_;
};

}  // namespace pn
